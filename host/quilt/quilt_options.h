#pragma once
//! Options, progress and statistics shared by the quilting drivers (planar and surface).

#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "core/error.h"
#include "quilt/geometry_matching.h"
#include "quilt/patch_step.h"

namespace meshquilt {

//! How far a synthesis has come, reported after every patch.
struct QuiltProgress {
  double covered_area = 0.0;  //!< area of processed cells (plane units, or base units for surfaces)
  double total_area = 0.0;    //!< area of all cells
  int processed_cells = 0;
  int total_cells = 0;
  int patches = 0;
};

struct QuiltOptions {
  int cells_across_swatch = 16;     //!< grid cells along the swatch's shorter x-y side
  double sub_patch_fraction = 0.5;  //!< output-sub-patch side / swatch side
  uint64_t seed = 1;                //!< seeds every random choice
  //! Eq. 1 weight of distance against normal difference, the one home of the paper's lambda.
  //! Eq. 1 is not scale invariant, so distances are measured in units of the swatch's mean edge
  //! length: lambda = 1 means "one edge length off costs as much as a unit normal difference" at
  //! every swatch scale. The drivers derive the stages' per-length weight from it (the `lambda`
  //! fields of `matching` and `step.correspondence` are not read).
  double lambda = 1.0;
  bool cleanup = true;              //!< drop elements that could not be made whole
  int max_patches = 0;              //!< stop after this many patches (0: until done); for inspection
  int seed_attempts = 3;            //!< a cell still uncovered after this many patches seeded on it is a hole
  //! Where a repeating swatch's pattern runs unbroken, its elements that stand alone
  //! (quilt/lattice_classes.h) are placed straight at its periods, not patch by patch: over a
  //! plane everywhere, over a base farther than this many periods (or widest elements) from the
  //! layout's cones and the base's border (surface/lattice_fill.h). 0 quilts every element.
  double fill_margin = 0.5;
  MatchingOptions matching;
  PatchStepOptions step;
  std::function<void(const QuiltProgress&)> progress;  //!< optional, called after every patch
  const CancelToken* cancel = nullptr;                 //!< optional: polled between and inside stages
};

//! What happened, for the stats JSON.
struct QuiltStats {
  int patches = 0;
  MergeCounts merges;
  int dropped_elements = 0;      //!< removed by the clean-up pass: open, folded and intersecting
  int dropped_open = 0;          //!< not closed 2-manifolds although the swatch's elements are
  int dropped_folded = 0;        //!< passed through themselves although the swatch's elements do not
  int cut_swatch_elements = 0;   //!< swatch elements cut open by its border, left out (prepare_swatch)
  int dropped_intersecting = 0;  //!< the smaller of two elements that pass through each other
  int joined_elements = 0;       //!< elements joined into one they met face to face
  int filled_elements = 0;       //!< placed straight at the pattern's periods (QuiltOptions::fill_margin)
  int cells = 0;
  double cell_size = 0.0;
  int holes = 0;                  //!< connected groups of cells left uncovered after seed_attempts patches
  int hole_cells = 0;             //!< cells in holes
  double largest_hole_area = 0.0; //!< area of the largest hole (plane units, or base units for surfaces)
  //! Patches are placed at the swatch's periods only: over a plane, where the swatch has a
  //! lattice; over a base, where the layout's seams also continue by them.
  bool on_lattice = false;
  glm::dvec2 plane_extent{0.0};   //!< planar synthesis: the plane covered is [0, plane_extent] in x-y
  std::map<std::string, double> stage_seconds;  //!< seed, match, correspondence, deform, merge, cleanup
  GridSource grid_source = GridSource::built;    //!< the matcher's nearest-face grid
};

}  // namespace meshquilt
