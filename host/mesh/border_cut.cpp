#include "mesh/border_cut.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <unordered_map>

#include "mesh/convex_outline.h"
#include "mesh/topology.h"

namespace meshquilt {

std::vector<uint8_t> cut_by_border(const std::vector<TriMesh>& elements) {
  std::vector<uint8_t> cut(elements.size(), 0);
  std::vector<glm::dvec2> points;
  for (const TriMesh& e : elements)
    for (const Tri& t : e.triangles)
      for (int32_t v : t) points.emplace_back(e.positions[v]);
  const ConvexOutline hull(std::move(points));
  if (hull.corners().size() < 3) return cut;
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
      if (hull.boundary_distance(p) <= reach) {
        cut[k] = 1;
        break;
      }
    }
  }
  return cut;
}

}  // namespace meshquilt
