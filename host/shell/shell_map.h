#pragma once
//! The shell map (Porumbescu et al. 2005; Section 3.2 of the mesh quilting paper): a piecewise
//! linear bijection between the geometry texture space and the shell, through barycentric
//! coordinates of corresponding tetrahedra.
//!
//! Texture space is each chart of the atlas times [0, H], H the shell height. Its prism over an
//! atlas triangle has the triangle at w = 0 and the top corners at (top_uv, H): the original shell
//! map puts each top corner over its base corner (top_uv = atlas uv); stretch minimization moves
//! the top corners of chart-interior vertices. Both prisms split into tetrahedra by the same rule
//! (prism_tetrahedra), so tetrahedron i of texture space maps linearly onto tetrahedron i of the
//! shell.
//!
//! A point of the synthesized texture (a base point and a height) is the texture point
//! (atlas uv of the base point, height). Heights below 0 or above H (element deformation makes a
//! few) use the affine map of the tetrahedron that holds the point clamped to [0, H], so the map
//! extends continuously beyond the shell; a point that no tetrahedron of its chart near its face
//! holds (rounding at chart edges) uses the nearest one the same way.

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <vector>

#include "shell/shell.h"
#include "shell/texture_atlas.h"

namespace meshquilt {

class ShellMap {
 public:
  //! `top_uv`: #A texture-plane position of each atlas vertex's top corner.
  //! \pre base, atlas and shell belong together; top_uv.size() == atlas.uv.size().
  ShellMap(const BaseSurface& base, const TextureAtlas& atlas, const Shell& shell,
           std::vector<glm::dvec2> top_uv);

  //! The shell point of a base point at `height` (base units).
  Vec3 to_shell(const SurfacePoint& point, double height) const;

  size_t tet_count() const { return 3 * base_.mesh.num_faces(); }
  //! Corners of tetrahedron i (3 per base face, prism_tetrahedra order) in texture space
  //! (u, v, w) and in the shell.
  std::array<glm::dvec3, 4> texture_tet(size_t i) const;
  std::array<Vec3, 4> shell_tet(size_t i) const;
  double texture_height() const { return shell_.height; }
  const std::vector<glm::dvec2>& top_uv() const { return top_uv_; }
  const TextureAtlas& atlas() const { return atlas_; }
  const Shell& shell() const { return shell_; }

 private:
  // Barycentrics of texture point q in tetrahedron i (b1, b2, b3; b0 = 1 - sum).
  glm::dvec3 barycentric(size_t i, const glm::dvec3& q) const;

  const BaseSurface& base_;
  const TextureAtlas& atlas_;
  const Shell& shell_;
  std::vector<glm::dvec2> top_uv_;
  std::vector<std::array<PrismTet, 3>> split_;  // #F
  std::vector<glm::dmat3> inverse_;             // #tets, inverse texture edge matrices
};

}  // namespace meshquilt
