#pragma once
//! The closest point on a triangle to a point: the one point-triangle distance of meshquilt's
//! host code, inline because the nearest-face grid and exact matching costs call it in their
//! innermost loops.

#include <algorithm>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A face and the closest point on it to a query point (double precision).
struct ClosestPoint {
  int32_t face = -1;      //!< -1: nothing within the search radius
  Vec3 point{0.0};        //!< closest point on `face`
  Vec3 barycentric{0.0};  //!< of `point` with respect to the face's three vertices
  double distance = std::numeric_limits<double>::infinity();
};

//! Closest point on triangle (a, b, c) to p, exact in double (Ericson's region test).
inline ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson, Real-Time Collision Detection, 5.1.5: find the Voronoi region of p.
  ClosestPoint out;
  auto finish = [&](double u, double v, double w) {
    out.barycentric = Vec3(u, v, w);
    out.point = u * a + v * b + w * c;
    out.distance = glm::length(p - out.point);
    return out;
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return finish(1, 0, 0);
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return finish(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  // Each edge region also needs the edge to have a length (its denominator is the squared
  // length): a zero-length edge would give 0 / 0; such a triangle has no area and is handled
  // below by its edges.
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) {
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return finish(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) {
    const double w = d2 / (d2 - d6);
    return finish(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - w, w);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // Degenerate (zero-area) triangle: the closest of its three edges.
    ClosestPoint best;
    const Vec3 v[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      const Vec3 e = v[(i + 1) % 3] - v[i];
      const double len2 = glm::dot(e, e);
      const double t = len2 > 0.0 ? std::clamp(glm::dot(p - v[i], e) / len2, 0.0, 1.0) : 0.0;
      const Vec3 q = v[i] + t * e;
      const double d = glm::length(p - q);
      if (d < best.distance) {
        best.distance = d;
        best.point = q;
        best.barycentric = Vec3(0.0);
        best.barycentric[i] = 1.0 - t;
        best.barycentric[(i + 1) % 3] = t;
      }
    }
    return best;
  }
  const double denom = 1.0 / sum;
  const double v = vb * denom, w = vc * denom;
  return finish(1.0 - v - w, v, w);
}

}  // namespace meshquilt
