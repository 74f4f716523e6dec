#pragma once
//! Mesh quilting over an arbitrary base mesh (Section 3.1 of the mesh quilting paper): the driver
//! that covers a surface. Cells are the base's triangles, split where they are large; each seed
//! grows a local patch flattened by a conformal map, turned so the guidance field at the seed runs
//! along the swatch's x axis, and the patch step (quilt/patch_step.h) runs in that plane. Output
//! vertices live in local coordinates (base face, barycentrics, height), so every later patch sees
//! them in its own plane; they are placed in space by an embedding (quilt/surface_embedding.h):
//! a shell map by default, or displacement along interpolated vertex normals (Figure 8, left).

#include <cstdint>

#include "inspect/copy_sizes.h"
#include "mesh/tri_mesh.h"
#include "surface/guidance_field.h"
#include "surface/cone_metric_field.h"
#include "surface/seamless_layout.h"
#include "surface/surface_embedding.h"
#include "quilt/quilt_options.h"

namespace meshquilt {

namespace engine {
class Device;
}

struct SurfaceQuiltOptions : QuiltOptions {
  //! The swatch's longer x-y side measures scale x the base's bounding-box diagonal.
  double scale = 0.1;
  //! Height of the layer in base units (0: the swatch's thickness at that scale).
  double shell_height = 0.0;
  //! A patch whose plane area over base area varies by more than this factor (max / min over its
  //! triangles) is shrunk, with its output sub-patch (the paper's rule). A patch seeded again on
  //! a cell that an earlier one left uncovered allows twice the distortion per earlier attempt.
  double max_area_distortion = 4.0;
  int max_shrinks = 4;  //!< shrink a patch at most this many times (by 0.75 each)
  //! Patches are windows of one layout of the base that follows the smoothest n-direction field
  //! holding the guidance field's given directions (surface/base_layout.h, docs/decisions/0033);
  //! off: each patch is flattened alone along the guidance field (docs/decisions/0032).
  bool shared_layout = true;
  //! n of that field: 1, 2 or 4; 0 takes the swatch's rotational symmetry (quilt/swatch_symmetry.h).
  int symmetry = 0;
  //! How strongly that layout holds elements to one size against keeping them their shape
  //! (seamless_layout.h): 0.1 conformal, 3-10 even sizes with stretched elements.
  double size_hold = kDefaultSizeHold;
  //! The bound on that layout's scale spread (p90 / p10 by area) that pairs of cones are added
  //! for, where no field was drawn on a closed genus-0 base or a disc (cone_metric_field.h).
  double cone_spread = kDefaultConeSpread;
  //! Where the pattern filled straight from the layout covers most of the base and its median
  //! element is off the size asked, lays the layout out again to bring it to that size.
  bool median_from_fill = true;
  //! Places local coordinates in space; empty: displacement along vertex normals.
  EmbeddingFactory embedding;
};

//! A synthesized layer: the embedded mesh and where each of its vertices lies over the base.
struct SurfaceQuilt {
  TriMesh mesh;                    //!< with per-face element ids and sources
  std::vector<LocalVertex> local;  //!< #V of mesh
};

//! What the surface driver adds to QuiltStats.
struct SurfaceQuiltStats : QuiltStats {
  int base_faces = 0;          //!< after welding
  int shrunk_patches = 0;      //!< patches shrunk for distortion, fold-overs or closing up
  int layout_windows = 0;      //!< patches laid out as windows of the shared layout
  int field_symmetry = 0;      //!< n of the layout's field (0 without a layout)
  int cones = 0;               //!< singular vertices of the layout's field
  std::vector<Vec3> cone_points;  //!< where they are on the base
  std::vector<int> cone_indices;  //!< the field's index at each, in units of 1 / field_symmetry
  double layout_scale_spread = 0.0;  //!< BaseLayout::scale_spread
  int outside_vertices = 0;    //!< vertices placed outside their patch, put on its nearest face
  double shell_height = 0.0;   //!< base units
  double diagonal = 0.0;       //!< base bounding-box diagonal
  double covered_area = 0.0;   //!< base area of processed cells that are not holes
  double hole_area = 0.0;      //!< base area of hole cells
  int intersecting_face_pairs = 0;  //!< face pairs of different elements meeting, before clean-up
  int synthesis_map_elements = 0;   //!< elements placed through the map synthesis decided on (place_elements)
  CopySizes element_size;           //!< whole copies' size over the size asked
  //! The shared layout laid out again with elements this many times its median's size, so that
  //! the filled median is the size asked (1: as first laid out).
  double size_correction = 1.0;
};

//! Grows a layer of `swatch` over `base` oriented by `field` (interpolate_field).
//! \pre base prepared by prepare_base.
//! \throw InputError for a degenerate swatch or a bad option; DeviceError, SolverError; Cancelled.
SurfaceQuilt quilt_surface(const TriMesh& swatch, const TriMesh& base, const GuidanceField& field,
                      engine::Device& device, const SurfaceQuiltOptions& options,
                      SurfaceQuiltStats* stats = nullptr);

}  // namespace meshquilt
