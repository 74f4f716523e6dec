#pragma once
//! Sizes of elements, and the two-sample Kolmogorov-Smirnov distance used to compare the size
//! distribution of a synthesized mesh with its swatch's.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Per-element measures, each #elements long.
struct ElementMeasures {
  std::vector<double> area;       //!< surface area (sum of face areas)
  std::vector<double> extent;     //!< largest side of the element's axis-aligned bounding box
  std::vector<double> xy_extent;  //!< larger of the box's x and y sides
};

//! Measures of each element. face_element: #F ids in [0, elements).
ElementMeasures element_measures(const TriMesh& mesh, const std::vector<int32_t>& face_element, int32_t elements);

//! Two-sample Kolmogorov-Smirnov statistic sup_x |F_a(x) - F_b(x)| of the empirical CDFs, in
//! [0, 1]. Values closer than `tie_tolerance` x the largest magnitude in either sample count as
//! ties (they are rounded to that step first), so copies of one element whose areas differ only
//! by floating-point rounding do not look like different distributions. NaN when a sample is empty.
double ks_distance(std::vector<double> a, std::vector<double> b, double tie_tolerance = 1e-9);

//! Median of the values (mean of the middle two for an even count); NaN when empty.
double median(std::vector<double> values);

}  // namespace meshquilt
