#include "inspect/yarn_lengths.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "inspect/element_statistics.h"

namespace meshquilt {

TubeMeasures tube_measures(const TriMesh& mesh, const std::vector<int32_t>& face_element, int32_t elements) {
  std::vector<double> area(static_cast<size_t>(elements), 0.0), volume(static_cast<size_t>(elements), 0.0);
  // Volumes are summed over tetrahedra to a corner of the element (not the origin): far from the
  // origin the terms would cancel.
  std::vector<Vec3> corner(static_cast<size_t>(elements));
  std::vector<uint8_t> has_corner(static_cast<size_t>(elements), 0);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const int32_t e = face_element[f];
    const Tri& t = mesh.triangles[f];
    if (!has_corner[e]) corner[e] = mesh.positions[t[0]], has_corner[e] = 1;
    const Vec3 a = mesh.positions[t[0]] - corner[e], b = mesh.positions[t[1]] - corner[e],
               c = mesh.positions[t[2]] - corner[e];
    area[e] += 0.5 * glm::length(glm::cross(b - a, c - a));
    volume[e] += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  TubeMeasures m;
  m.length.assign(static_cast<size_t>(elements), 0.0);
  m.radius.assign(static_cast<size_t>(elements), 0.0);
  for (int32_t e = 0; e < elements; ++e) {
    if (!(volume[e] > 0.0) || !(area[e] > 0.0)) continue;
    m.length[e] = area[e] * area[e] / (4.0 * std::numbers::pi * volume[e]);
    m.radius[e] = 2.0 * volume[e] / area[e];
  }
  return m;
}

double median_tube_radius(const TubeMeasures& tubes, int32_t* count) {
  std::vector<double> radii;
  for (size_t e = 0; e < tubes.length.size(); ++e)
    if (tubes.length[e] > 0.0) radii.push_back(tubes.radius[e]);
  if (count) *count = static_cast<int32_t>(radii.size());
  return radii.empty() ? 0.0 : median(radii);
}

double length_weighted_median(std::vector<double> lengths) {
  lengths.erase(std::remove_if(lengths.begin(), lengths.end(), [](double l) { return !(l > 0.0); }), lengths.end());
  if (lengths.empty()) return 0.0;
  std::sort(lengths.begin(), lengths.end());
  double total = 0.0;
  for (double l : lengths) total += l;
  double running = 0.0;
  for (double l : lengths) {
    running += l;
    if (running >= 0.5 * total) return l;
  }
  return lengths.back();
}

}  // namespace meshquilt
