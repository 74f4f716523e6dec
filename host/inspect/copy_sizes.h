#pragma once
//! How large each element came out against the size asked: an output element that is a whole
//! copy of a swatch element (as many vertices) against that element at the job's scale.

#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! The size distribution of whole copies, over the size asked.
struct CopySizes {
  int copies = 0;  //!< output elements measured (whole copies of closed swatch elements)
  double p10 = 0.0, median = 0.0, p90 = 0.0;
};

//! Root mean square distance of the points from their mean (0 for none).
double gyration(const std::vector<Vec3>& points);

//! Size is the radius of gyration (root mean square distance of an element's vertices from their
//! mean). `output` carries per-face elements and sources; `swatch_elements[s]` is source s in
//! swatch units, `unit` base units per swatch unit. Elements stitched or cut (other vertex counts
//! than their source) are left out.
CopySizes copy_sizes(const TriMesh& output, const std::vector<TriMesh>& swatch_elements, double unit);

}  // namespace meshquilt
