#include "inspect/copy_sizes.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace meshquilt {
namespace {

double quantile(std::vector<double>& values, double q) {
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(q * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

double gyration(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 mean(0.0);
  for (const Vec3& p : points) mean += p / static_cast<double>(points.size());
  double sum = 0.0;
  for (const Vec3& p : points) sum += glm::dot(p - mean, p - mean);
  return std::sqrt(sum / static_cast<double>(points.size()));
}

CopySizes copy_sizes(const TriMesh& output, const std::vector<TriMesh>& swatch_elements, double unit) {
  CopySizes out;
  if (output.elements.size() != output.num_faces() || output.sources.size() != output.num_faces()) return out;
  int32_t count = 0;
  for (int32_t e : output.elements) count = std::max(count, e + 1);
  std::vector<std::vector<Vec3>> points(static_cast<size_t>(count));
  std::vector<int32_t> source(static_cast<size_t>(count), -1), seen(output.num_vertices(), -1);
  for (size_t f = 0; f < output.num_faces(); ++f) {
    const int32_t e = output.elements[f];
    source[e] = output.sources[f];
    for (int32_t v : output.triangles[f])
      if (seen[v] != e) {
        seen[v] = e;
        points[e].push_back(output.positions[v]);
      }
  }
  std::vector<double> asked(swatch_elements.size());
  for (size_t s = 0; s < swatch_elements.size(); ++s) asked[s] = unit * gyration(swatch_elements[s].positions);
  std::vector<double> ratios;
  for (int32_t e = 0; e < count; ++e) {
    const int32_t s = source[e];
    if (s < 0 || s >= static_cast<int32_t>(swatch_elements.size()) || !(asked[s] > 0.0) ||
        points[e].size() != swatch_elements[s].positions.size())
      continue;
    ratios.push_back(gyration(points[e]) / asked[s]);
  }
  out.copies = static_cast<int>(ratios.size());
  if (ratios.empty()) return out;
  out.p10 = quantile(ratios, 0.1);
  out.median = quantile(ratios, 0.5);
  out.p90 = quantile(ratios, 0.9);
  return out;
}

}  // namespace meshquilt
