#pragma once
//! A woven swatch as a loom exemplar (paper 004, Section 6, from a mesh instead of a CT volume):
//! its yarns found, its crossing grid registered and its binary weave pattern read.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"
#include "swatch/weave_pattern.h"

namespace meshquilt {

//! What a woven mesh holds. In the registered frame (the mesh turned by -tilt about z) warps run
//! along y and wefts along x; warp i's centre is at x = origin.x + i pitch.x and weft j's at
//! y = origin.y + j pitch.y.
struct ExemplarWeave {
  double tilt = 0.0;                  //!< radians: the warps' direction is (-sin, cos) of it
  glm::dvec2 origin{0.0};             //!< x of warp 0, y of weft 0 (registered frame)
  glm::dvec2 pitch{0.0};              //!< between neighbouring warps (x) and wefts (y)
  std::vector<int32_t> warp_elements;  //!< element id of warp i, by increasing x
  std::vector<int32_t> weft_elements;  //!< element id of weft j, by increasing y
  //! warps x wefts; over(i, j): warp i lies above weft j where they cross. Indices outside the
  //! exemplar are not blocks of it (over() wraps them; callers keep to the interior).
  WeavePattern pattern;
  double yarn_radius = 0.0;  //!< median half-thickness of the yarns across their run
};

//! `p` in the registered frame: turned by -tilt about z.
Vec3 registered_point(const ExemplarWeave& weave, const Vec3& p);

//! The element of each face as registration reads it: PLY `element` ids, else components.
std::vector<int32_t> yarn_face_elements(const TriMesh& mesh);

//! Registers `mesh` (its elements: PLY `element` ids or connected components) as an exemplar.
//! \throw InputError(invalid_mesh) naming `name` when an element is not a yarn (not at least
//!        twice as long along the weave's axes as across), there are fewer than three warps or
//!        wefts, their spacing varies by more than a fifth of the pitch, or a warp and a weft do
//!        not cross where the grid says.
ExemplarWeave register_exemplar(const TriMesh& mesh, const std::string& name);

}  // namespace meshquilt
