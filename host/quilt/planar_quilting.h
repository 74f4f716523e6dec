#pragma once
//! Planar mesh quilting (Section 2 of the mesh quilting paper): the driver that fills a
//! rectangle. It owns a cell grid over the rectangle and a seed finder, and runs the patch step
//! (quilt/patch_step.h) in the output plane itself until every cell is processed, then removes the
//! elements that could not be made whole (quilt/broken_elements.h).

#include "mesh/tri_mesh.h"
#include "quilt/quilt_options.h"

namespace meshquilt {

namespace engine {
class Device;
}

struct PlanarQuiltOptions : QuiltOptions {
  double width = 4.0;   //!< output size along x, in swatch extents
  double height = 4.0;  //!< output size along y, in swatch extents
  //! Place a repeating swatch at its periods only (quilt/swatch_lattice.h); false: at any cell
  //! translation matching chooses, refined.
  bool lattice_placement = true;
};

//! Grows a planar layer of `options.width x options.height` swatch extents from `swatch` (any
//! orientation: it is put in its swatch frame first). Returns the output mesh with per-face
//! element ids and sources (the swatch element each face was copied from). \throw InputError for a degenerate swatch; DeviceError, SolverError; Cancelled.
TriMesh quilt_plane(const TriMesh& swatch, engine::Device& device, const PlanarQuiltOptions& options,
                    QuiltStats* stats = nullptr);

}  // namespace meshquilt
