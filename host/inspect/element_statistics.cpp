#include "inspect/element_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace meshquilt {

ElementMeasures element_measures(const TriMesh& mesh, const std::vector<int32_t>& face_element, int32_t elements) {
  ElementMeasures out;
  out.area.assign(elements, 0.0);
  std::vector<Vec3> lo(elements, Vec3(std::numeric_limits<double>::infinity()));
  std::vector<Vec3> hi(elements, Vec3(-std::numeric_limits<double>::infinity()));
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    const int32_t e = face_element[f];
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    out.area[e] += 0.5 * glm::length(glm::cross(b - a, c - a));
    lo[e] = glm::min(lo[e], glm::min(a, glm::min(b, c)));
    hi[e] = glm::max(hi[e], glm::max(a, glm::max(b, c)));
  }
  out.extent.resize(elements);
  out.xy_extent.resize(elements);
  for (int32_t e = 0; e < elements; ++e) {
    const Vec3 size = hi[e] - lo[e];
    out.xy_extent[e] = std::max(size.x, size.y);
    out.extent[e] = std::max(out.xy_extent[e], size.z);
  }
  return out;
}

double ks_distance(std::vector<double> a, std::vector<double> b, double tie_tolerance) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::quiet_NaN();
  double largest = 0.0;
  for (double x : a) largest = std::max(largest, std::abs(x));
  for (double x : b) largest = std::max(largest, std::abs(x));
  const double step = tie_tolerance * largest;
  if (step > 0.0) {
    for (double& x : a) x = std::round(x / step) * step;
    for (double& x : b) x = std::round(x / step) * step;
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
  double d = 0.0;
  size_t i = 0, j = 0;
  // Step through the pooled values in order; ties advance both samples before comparing, so
  // the difference is taken between the CDFs at the same x.
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    d = std::max(d, std::abs(i / na - j / nb));
  }
  return d;
}

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + mid));
}

}  // namespace meshquilt
