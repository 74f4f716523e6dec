#pragma once
//! Scheduling cells on a base mesh (Section 3.1 of the mesh quilting paper uses the base's
//! triangles): triangles wider than the cell size are split into a regular lattice of m x m
//! sub-triangles, so no cell is wider than a fraction of the output sub-patch. Cells only schedule:
//! local coordinates still refer to the original triangles.

#include <cstdint>
#include <vector>

#include "surface/conformal_patch.h"

namespace meshquilt {

struct SurfaceCells {
  std::vector<SurfacePoint> centres;                //!< #cells, centroid of each cell
  std::vector<double> areas;                        //!< #cells
  std::vector<int32_t> face_offsets;                //!< #F + 1: cells of face f are [offsets[f], offsets[f+1])
  std::vector<std::vector<int32_t>> neighbours;     //!< #cells, cells whose centres are close (symmetric)
};

//! Splits every face into m^2 cells, m = ceil(longest edge / cell_size), and links cells whose
//! centres lie closer than 1.5 x the larger of their two sizes (size = longest edge / m).
//! \pre cell_size > 0
SurfaceCells make_surface_cells(const BaseSurface& base, double cell_size);

}  // namespace meshquilt
