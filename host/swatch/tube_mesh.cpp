#include "swatch/tube_mesh.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace meshquilt {

void append_tube(TriMesh& mesh, const std::vector<Vec3>& centre, const std::vector<Vec3>& normal,
                 double radius, int sides, TubeEnds ends, int32_t element,
                 const std::vector<Vec3>& tangent_given) {
  const int count = static_cast<int>(centre.size());
  const bool loop = ends == TubeEnds::loop;
  const auto base = static_cast<int32_t>(mesh.positions.size());
  for (int k = 0; k < count; ++k) {
    // Central differences (one-sided at open ends) give a tangent that is symmetric in the
    // neighbours, so a periodic centreline gives a periodic surface.
    const int prev = loop ? (k + count - 1) % count : std::max(k - 1, 0);
    const int next = loop ? (k + 1) % count : std::min(k + 1, count - 1);
    const Vec3 tangent = glm::normalize(tangent_given.empty() ? centre[next] - centre[prev] : tangent_given[k]);
    const Vec3 n = glm::normalize(normal[k] - glm::dot(normal[k], tangent) * tangent);
    const Vec3 b = glm::cross(tangent, n);
    for (int s = 0; s < sides; ++s) {
      const double a = 2.0 * std::numbers::pi * s / sides;
      mesh.positions.push_back(centre[k] + radius * (std::cos(a) * n + std::sin(a) * b));
    }
  }
  auto vertex = [&](int k, int s) { return base + (k % count) * sides + (s % sides); };
  // (n, b, tangent) is right-handed, so stepping around the section and then along the tube
  // gives the outward normal for the corner order below.
  const int segments = loop ? count : count - 1;
  for (int k = 0; k < segments; ++k) {
    for (int s = 0; s < sides; ++s) {
      const int32_t a = vertex(k, s), b = vertex(k, s + 1), c = vertex(k + 1, s + 1), d = vertex(k + 1, s);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  }
  if (!loop) {
    const auto start = static_cast<int32_t>(mesh.positions.size());
    mesh.positions.push_back(centre.front());
    mesh.positions.push_back(centre.back());
    for (int s = 0; s < sides; ++s) {
      mesh.triangles.push_back({start, vertex(0, s + 1), vertex(0, s)});
      mesh.triangles.push_back({start + 1, vertex(count - 1, s), vertex(count - 1, s + 1)});
    }
  }
  mesh.elements.resize(mesh.triangles.size(), element);
}

}  // namespace meshquilt
