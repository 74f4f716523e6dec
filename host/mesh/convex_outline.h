#pragma once
//! The convex x-y outline of a swatch's geometry. A swatch turned in its plane fills only part of
//! its bounding rectangle: the corners outside the outline hold nothing, by shape, not by design
//! of a sparse pattern, so they must not count as covered.

#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A convex polygon of the x-y plane.
class ConvexOutline {
 public:
  ConvexOutline() = default;
  //! The convex hull of the points (Andrew's monotone chain).
  explicit ConvexOutline(std::vector<glm::dvec2> points);
  //! The convex hull of the points' x-y projections.
  explicit ConvexOutline(const std::vector<Vec3>& points);

  //! Whether `p` lies inside the outline grown outward by `margin` (each edge moved out by
  //! `margin`, so corners grow a little more). An empty outline contains nothing; one of one or
  //! two points contains what lies within `margin` of them.
  bool contains(const glm::dvec2& p, double margin = 0.0) const;

  //! Distance from `p` to the outline's boundary (its edges), inside or out; infinity when empty.
  double boundary_distance(const glm::dvec2& p) const;

  //! The least distance between two parallel lines enclosing the outline (its width across its
  //! narrowest direction: a diagonal yarn's thickness, not its bounding box); 0 below 3 corners.
  double width() const;

  //! Corners in counter-clockwise order, no three collinear.
  const std::vector<glm::dvec2>& corners() const { return corners_; }

 private:
  std::vector<glm::dvec2> corners_;
};

}  // namespace meshquilt
