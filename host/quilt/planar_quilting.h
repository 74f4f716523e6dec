#pragma once
//! Planar mesh quilting (Section 2 of the mesh quilting paper): the host scheduler that repeats
//! seed finding, geometry matching, element correspondences, element deformation and element
//! merging until every cell of the output grid is processed, then removes elements that could
//! not be made whole.
//!
//! The scheduler works in a 2D parameter plane with the swatch frame's z as height, so the same
//! loop can run inside a surface patch's conformal parameter plane.

#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "mesh/tri_mesh.h"
#include "quilt/correspondence.h"
#include "quilt/element_deformation.h"
#include "quilt/element_merging.h"
#include "quilt/geometry_matching.h"

namespace meshquilt {

namespace engine {
class Device;
}

//! How far the synthesis has come, reported after every patch.
struct QuiltProgress {
  int processed_cells = 0;
  int total_cells = 0;
  int patches = 0;
};

struct PlanarQuiltOptions {
  double width = 4.0;   //!< output size along x, in swatch extents
  double height = 4.0;  //!< output size along y, in swatch extents
  int cells_across_swatch = 16;      //!< grid cells along the swatch's shorter x-y side
  double sub_patch_fraction = 0.5;   //!< output-sub-patch side / swatch side
  uint64_t seed = 1;                 //!< seeds every random choice
  //! Eq. 1 weight of distance against normal difference. Eq. 1 is not scale invariant, so
  //! distances are measured in units of the swatch's mean edge length: lambda = 1 then means
  //! "one edge length off costs as much as a unit normal difference" at every swatch scale. It
  //! overrides matching.lambda and correspondence.lambda.
  double lambda = 1.0;
  double partner_distance = 0.5;     //!< merge partners' mean pair distance, in mean edge lengths, at most
  bool cleanup = true;               //!< drop elements that could not be made whole
  int max_patches = 0;               //!< stop after this many patches (0: until done); for inspection
  MatchingOptions matching;
  CorrespondenceOptions correspondence;
  DeformationOptions deformation;
  MergeOptions merging;
  std::function<void(const QuiltProgress&)> progress;  //!< optional, called after every patch
};

//! What happened, for the stats JSON.
struct QuiltStats {
  int patches = 0;
  int stitched = 0;           //!< related pairs cut and stitched into one element
  int replaced = 0;           //!< output elements replaced by an input element (kept_in)
  int kept = 0;               //!< input elements that yielded to an output element (kept_out)
  int rejected_inputs = 0;    //!< unrelated input elements that would have collided
  int refused_merges = 0;     //!< merges whose result would have passed through a neighbour
  int undone_deformations = 0;  //!< output deformations undone because they hit a neighbour
  int dropped_elements = 0;   //!< removed by the clean-up pass: dropped_open + dropped_intersecting
  int dropped_open = 0;       //!< not closed 2-manifolds although the swatch's elements are
  int dropped_intersecting = 0;  //!< the smaller of two elements that pass through each other
  int cells = 0;
  double cell_size = 0.0;
  std::map<std::string, double> stage_seconds;  //!< seed, match, correspondence, deform, merge, cleanup
};

//! Grows a planar layer of `options.width x options.height` swatch extents from `swatch` (any
//! orientation: it is put in its swatch frame first). Returns the output mesh with per-face
//! element ids. \throw InputError for a degenerate swatch; DeviceError, SolverError.
TriMesh quilt_plane(const TriMesh& swatch, engine::Device& device, const PlanarQuiltOptions& options,
                    QuiltStats* stats = nullptr);

}  // namespace meshquilt
