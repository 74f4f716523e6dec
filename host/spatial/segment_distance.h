#pragma once
//! Distance from a point to a segment: the one closest-point-on-segment of meshquilt.

#include <algorithm>

#include <glm/geometric.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Euclidean distance from p to the closed segment [a, b] (to a when a == b). When `t` is given
//! it receives the parameter of the closest point a + t (b - a), t in [0, 1].
inline double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b, double* t = nullptr) {
  const Vec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double along = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  if (t) *t = along;
  return glm::length(p - (a + along * ab));
}

}  // namespace meshquilt
