#include "mesh/border_cut.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <unordered_map>

#include "mesh/topology.h"

namespace meshquilt {
namespace {

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain: the hull's corners, counter-clockwise.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> points) {
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

}  // namespace

std::vector<uint8_t> cut_by_border(const std::vector<TriMesh>& elements) {
  std::vector<uint8_t> cut(elements.size(), 0);
  std::vector<glm::dvec2> points;
  for (const TriMesh& e : elements)
    for (const Tri& t : e.triangles)
      for (int32_t v : t) points.emplace_back(e.positions[v]);
  const std::vector<glm::dvec2> hull = convex_hull(std::move(points));
  if (hull.size() < 3) return cut;
  for (size_t k = 0; k < elements.size(); ++k) {
    const TriMesh& e = elements[k];
    std::unordered_map<uint64_t, int> uses;
    for (const Tri& t : e.triangles)
      for (int c = 0; c < 3; ++c) ++uses[undirected_edge_key(t[c], t[(c + 1) % 3])];
    std::vector<int32_t> rim;
    double rim_length = 0.0;
    for (const Tri& t : e.triangles)
      for (int c = 0; c < 3; ++c) {
        const int32_t a = t[c], b = t[(c + 1) % 3];
        if (uses[undirected_edge_key(a, b)] != 1) continue;
        rim.push_back(a);
        rim_length += glm::length(e.positions[b] - e.positions[a]);
      }
    if (rim.empty()) continue;  // closed (or only non-manifold): not cut by the crop
    const double reach = 1.5 * rim_length / static_cast<double>(rim.size());
    for (int32_t v : rim) {
      const glm::dvec2 p(e.positions[v]);
      bool near = false;
      for (size_t h = 0; h < hull.size() && !near; ++h)
        near = distance_to_segment(p, hull[h], hull[(h + 1) % hull.size()]) <= reach;
      if (near) {
        cut[k] = 1;
        break;
      }
    }
  }
  return cut;
}

}  // namespace meshquilt
