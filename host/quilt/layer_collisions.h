#pragma once
//! The patch step's collision policy (quilt_policies.h's passes_through, applied to the layer):
//! whether an element, once placed, would pass through a layer element other than itself or
//! through an obstacle, in the space the output will live in.

#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/tri_mesh.h"
#include "quilt/patch_step.h"

namespace meshquilt {

//! Collision checks against one growing layer, for one patch. Each layer element's face runs
//! (and, over a curved base, its placement in space) are measured once per shape: a patch tests
//! some thirty candidates against much the same neighbours. Call forget(k) when element k's shape
//! changes. The layer may grow between calls, never during one.
class LayerCollisions {
 public:
  //! `request` gives to_space (empty: the plane is the space) and the obstacles; both it and
  //! `layer` outlive this object. Only the elements `near` (ascending) and those appended after
  //! construction are tested against.
  LayerCollisions(const std::vector<PlaneElement>& layer, const PatchRequest& request, std::vector<int32_t> near);

  //! True when `mesh` (in plane coordinates) would pass through an alive layer element other than
  //! `self` and `also` (-1: none), or through an obstacle.
  bool collides(const TriMesh& mesh, int32_t self, int32_t also = -1);

  //! Element k changed shape: its measures are taken again when next needed.
  void forget(size_t k);

 private:
  bool collides_in_plane(const TriMesh& mesh, int32_t self, int32_t also);
  const std::vector<Box3>& runs_of(size_t k);
  // A layer element in space: over a curved base, elements apart in the plane can meet in space
  // (where normals converge over a concave part, or a patch wraps around a thin part), so
  // neighbours there are found by their boxes in space, not in the plane.
  const SpaceMesh& placed(size_t k);

  // The elements to test against: near_, then every index from first_new_.
  template <typename Visit>
  void for_each_candidate(Visit&& visit) const;

  const std::vector<PlaneElement>& layer_;
  const PatchRequest& request_;
  std::vector<int32_t> near_;
  size_t first_new_;
  std::vector<std::optional<std::vector<Box3>>> runs_;
  std::vector<std::optional<SpaceMesh>> in_space_;
  std::vector<Box3> obstacle_bounds_;
  std::vector<std::vector<Box3>> obstacle_runs_;
};

}  // namespace meshquilt
