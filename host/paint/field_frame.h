#pragma once
//! The frame paint reads a vertex's neighbourhood in: x along the field, y along normal x field,
//! lengths in sample pixels. The sweep, the carry to a finer level and the rigid patches all read
//! offsets in it, and must agree to the bit.

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct FieldFrame {
  Vec3 x;  //!< the field, unit and tangent
  Vec3 y;  //!< normal x field
};

inline FieldFrame field_frame(const Vec3& normal, const Vec3& direction) {
  return {direction, glm::normalize(glm::cross(normal, direction))};
}

//! `q` (a vector in space from the frame's vertex) in the frame, at `pixels_per_unit`.
inline glm::dvec2 frame_offset(const FieldFrame& frame, const Vec3& q, double pixels_per_unit) {
  return pixels_per_unit * glm::dvec2(glm::dot(q, frame.x), glm::dot(q, frame.y));
}

}  // namespace meshquilt
