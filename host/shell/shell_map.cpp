#include "shell/shell_map.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <limits>

namespace meshquilt {

ShellMap::ShellMap(const BaseSurface& base, const TextureAtlas& atlas, const Shell& shell,
                   std::vector<glm::dvec2> top_uv)
    : base_(base), atlas_(atlas), shell_(shell), top_uv_(std::move(top_uv)) {
  const size_t faces = base.mesh.num_faces();
  split_.resize(faces);
  inverse_.resize(3 * faces);
  for (size_t f = 0; f < faces; ++f) {
    split_[f] = prism_tetrahedra(base.mesh.triangles[f]);
    for (size_t j = 0; j < 3; ++j) {
      const std::array<glm::dvec3, 4> q = texture_tet(3 * f + j);
      const glm::dmat3 edges(q[1] - q[0], q[2] - q[0], q[3] - q[0]);
      const double det = glm::determinant(edges);
      inverse_[3 * f + j] = det != 0.0 ? glm::inverse(edges) : glm::dmat3(0.0);
    }
  }
}

std::array<glm::dvec3, 4> ShellMap::texture_tet(size_t i) const {
  const size_t f = i / 3;
  const std::array<int32_t, 3>& corners = atlas_.corners[f];
  std::array<glm::dvec3, 4> q;
  for (int k = 0; k < 4; ++k) {
    const PrismCorner c = split_[f][i % 3][k];
    const int32_t a = corners[c.k];
    q[k] = c.top ? glm::dvec3(top_uv_[a], shell_.height) : glm::dvec3(atlas_.uv[a], 0.0);
  }
  return q;
}

std::array<Vec3, 4> ShellMap::shell_tet(size_t i) const {
  const size_t f = i / 3;
  std::array<Vec3, 4> s;
  for (int k = 0; k < 4; ++k)
    s[k] = shell_.corner(base_.mesh.triangles[f], split_[f][i % 3][k], base_.mesh.positions);
  return s;
}

glm::dvec3 ShellMap::barycentric(size_t i, const glm::dvec3& q) const {
  const size_t f = i / 3;
  const PrismCorner c = split_[f][i % 3][0];
  const int32_t a = atlas_.corners[f][c.k];
  const glm::dvec3 q0 = c.top ? glm::dvec3(top_uv_[a], shell_.height) : glm::dvec3(atlas_.uv[a], 0.0);
  return inverse_[i] * (q - q0);
}

Vec3 ShellMap::to_shell(const SurfacePoint& point, double height) const {
  const int32_t face = point.face;
  const int32_t chart = atlas_.face_chart[face];
  const glm::dvec2 uv = atlas_.to_texture(point);
  const glm::dvec3 clamped(uv, std::clamp(height, 0.0, shell_.height));
  // The tetrahedron holding the clamped point: the face's prism first (the original map's top
  // corners are right above), then the prisms around its corners, then one ring further.
  size_t best = 3 * static_cast<size_t>(face);
  double best_margin = -std::numeric_limits<double>::infinity();
  const auto try_face = [&](int32_t f) {
    for (size_t j = 0; j < 3; ++j) {
      const size_t i = 3 * static_cast<size_t>(f) + j;
      const glm::dvec3 b = barycentric(i, clamped);
      const double margin = std::min({1.0 - b.x - b.y - b.z, b.x, b.y, b.z});
      if (margin > best_margin) {
        best_margin = margin;
        best = i;
      }
    }
  };
  constexpr double inside = -1e-9;
  try_face(face);
  std::vector<int32_t> ring{face};
  for (int depth = 0; depth < 2 && best_margin < inside; ++depth) {
    std::vector<int32_t> next;
    for (int32_t f : ring)
      for (int32_t v : base_.mesh.triangles[f])
        for (int32_t g : base_.vertex_faces[v])
          if (atlas_.face_chart[g] == chart) next.push_back(g);
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    for (int32_t g : next) try_face(g);
    ring = std::move(next);
  }
  const glm::dvec3 b = barycentric(best, glm::dvec3(uv, height));
  const std::array<Vec3, 4> s = shell_tet(best);
  return (1.0 - b.x - b.y - b.z) * s[0] + b.x * s[1] + b.y * s[2] + b.z * s[3];
}

}  // namespace meshquilt
