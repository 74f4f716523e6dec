#pragma once
//! Axis-aligned rectangles of a parameter plane.

#include <limits>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A closed axis-aligned rectangle [lo, hi] of the plane.
struct Rect2 {
  glm::dvec2 lo{0.0}, hi{0.0};
  bool contains(const glm::dvec2& p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
  bool contains(const Vec3& p) const { return contains(glm::dvec2(p)); }
  bool overlaps(const Rect2& o) const { return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y; }
};

//! x-y bounds of a mesh's vertices (an empty rectangle with lo > hi for no vertices).
inline Rect2 xy_bounds(const TriMesh& mesh) {
  Rect2 r{glm::dvec2(std::numeric_limits<double>::max()), glm::dvec2(std::numeric_limits<double>::lowest())};
  for (const Vec3& p : mesh.positions) {
    r.lo = glm::min(r.lo, glm::dvec2(p));
    r.hi = glm::max(r.hi, glm::dvec2(p));
  }
  return r;
}

}  // namespace meshquilt
