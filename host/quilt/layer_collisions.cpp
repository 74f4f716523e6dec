#include "quilt/layer_collisions.h"

#include "mesh/measures.h"
#include "quilt/quilt_policies.h"

namespace meshquilt {

LayerCollisions::LayerCollisions(const std::vector<PlaneElement>& layer, const PatchRequest& request,
                                 std::vector<int32_t> near)
    : layer_(layer), request_(request), near_(std::move(near)), first_new_(layer.size()) {
  for (const TriMesh& m : request.obstacles) {
    obstacle_bounds_.push_back(bounding_box(m.positions));
    obstacle_runs_.push_back(face_run_boxes(m));
  }
}

template <typename Visit>
void LayerCollisions::for_each_candidate(Visit&& visit) const {
  for (int32_t k : near_) visit(static_cast<size_t>(k));
  for (size_t k = first_new_; k < layer_.size(); ++k) visit(k);
}

bool LayerCollisions::collides(const TriMesh& mesh, int32_t self, int32_t also) {
  if (!request_.to_space) return collides_in_plane(mesh, self, also);
  const TriMesh placed_mesh = request_.to_space(mesh);
  const Box3 box = bounding_box(placed_mesh.positions);
  // Grown before any pointer into it is taken.
  in_space_.resize(layer_.size());
  std::vector<CollisionMesh> near;
  for_each_candidate([&](size_t k) {
    const auto index = static_cast<int32_t>(k);
    if (!layer_[k].alive || index == self || index == also) return;
    const SpaceMesh& other = placed(k);
    if (other.box.overlaps(box)) near.push_back({&other.mesh, &other.runs});
  });
  for (size_t k = 0; k < request_.obstacles.size(); ++k)
    if (obstacle_bounds_[k].overlaps(box)) near.push_back({&request_.obstacles[k], &obstacle_runs_[k]});
  return passes_through(placed_mesh, near);
}

void LayerCollisions::forget(size_t k) {
  if (k < in_space_.size()) in_space_[k].reset();
  if (k < runs_.size()) runs_[k].reset();
}

bool LayerCollisions::collides_in_plane(const TriMesh& mesh, int32_t self, int32_t also) {
  const Rect2 b = xy_bounds(mesh);
  runs_.resize(layer_.size());  // before any pointer into it is taken
  std::vector<CollisionMesh> near;
  for_each_candidate([&](size_t k) {
    const auto index = static_cast<int32_t>(k);
    if (layer_[k].alive && index != self && index != also && layer_[k].bounds.overlaps(b))
      near.push_back({&layer_[k].mesh, &runs_of(k)});
  });
  return passes_through(mesh, near);
}

const std::vector<Box3>& LayerCollisions::runs_of(size_t k) {
  if (!runs_[k]) runs_[k] = face_run_boxes(layer_[k].mesh);
  return *runs_[k];
}

const SpaceMesh& LayerCollisions::placed(size_t k) {
  if (layer_[k].in_space && !layer_[k].changed) return *layer_[k].in_space;
  if (!in_space_[k]) {
    TriMesh mesh = request_.to_space(layer_[k].mesh);
    const Box3 box = bounding_box(mesh.positions);
    std::vector<Box3> runs = face_run_boxes(mesh);
    in_space_[k].emplace(SpaceMesh{std::move(mesh), box, std::move(runs)});
  }
  return *in_space_[k];
}

}  // namespace meshquilt
