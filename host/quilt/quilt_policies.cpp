#include "quilt/quilt_policies.h"

#include <algorithm>
#include <atomic>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/parallel_for.h>

#include "mesh/measures.h"
#include "spatial/box_grid.h"
#include "spatial/triangle_intersection.h"

namespace meshquilt {

std::vector<const ElementRelation*> choose_partners(const Correspondences& correspondences, size_t outputs,
                                                    size_t inputs, double max_mean_distance,
                                                    std::vector<uint8_t>& in_partnered) {
  std::vector<const ElementRelation*> partners;
  in_partnered.assign(inputs, 0);
  std::vector<uint8_t> out_partnered(outputs, 0);
  for (const ElementRelation& relation : correspondences.relations) {
    if (out_partnered[relation.out_element] || in_partnered[relation.in_element]) continue;
    double distance = 0.0;
    for (int32_t k : relation.pairs) distance += correspondences.pairs[k].distance;
    if (distance > max_mean_distance * static_cast<double>(relation.pairs.size())) continue;
    out_partnered[relation.out_element] = in_partnered[relation.in_element] = 1;
    partners.push_back(&relation);
  }
  return partners;
}

namespace {

Box3 face_box(const TriMesh& mesh, const Tri& t) {
  const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  return Box3{glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)};
}

}  // namespace

std::vector<Box3> face_run_boxes(const TriMesh& mesh) {
  std::vector<Box3> runs((mesh.num_faces() + kFaceRun - 1) / kFaceRun);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Box3 b = face_box(mesh, mesh.triangles[f]);
    Box3& run = runs[f / kFaceRun];
    run = {glm::min(run.lo, b.lo), glm::max(run.hi, b.hi)};
  }
  return runs;
}

bool passes_through(const TriMesh& candidate, const std::vector<const TriMesh*>& others) {
  std::vector<std::vector<Box3>> runs;
  runs.reserve(others.size());
  std::vector<CollisionMesh> indexed;
  for (const TriMesh* other : others) indexed.push_back({other, &runs.emplace_back(face_run_boxes(*other))});
  return passes_through(candidate, indexed);
}

bool passes_through(const TriMesh& candidate, const std::vector<CollisionMesh>& others) {
  if (others.empty() || candidate.num_faces() == 0) return false;
  // Only candidate-against-other pairs are tested, through a hash of the candidate's faces
  // (cells about four faces across), and the first intersection ends the search.
  Box3 whole;
  std::vector<Box3> boxes(candidate.num_faces());
  double extent = 0.0;
  for (size_t f = 0; f < candidate.num_faces(); ++f) {
    boxes[f] = face_box(candidate, candidate.triangles[f]);
    whole = {glm::min(whole.lo, boxes[f].lo), glm::max(whole.hi, boxes[f].hi)};
    const Vec3 size = boxes[f].extent();
    extent += std::max({size.x, size.y, size.z});
  }
  BoxGrid grid(std::max(4.0 * extent / static_cast<double>(candidate.num_faces()),
                        1e-12 * glm::length(whole.extent()) + 1e-300));
  for (size_t f = 0; f < candidate.num_faces(); ++f) grid.insert(static_cast<int32_t>(f), boxes[f].lo, boxes[f].hi);
  const auto& x = candidate.positions;
  // The others are searched side by side; any hit ends every search (the answer is the same
  // whichever finds it). A run of an other's faces whose box misses the candidate's holds no
  // face that can meet it: on a 4 x 4 twill, 2% of the faces of the others met lie in the
  // candidate's box.
  std::atomic<bool> found{false};
  tbb::parallel_for(size_t{0}, others.size(), [&](size_t o) {
    const TriMesh& other = *others[o].mesh;
    const std::vector<Box3>& runs = *others[o].runs;
    const auto& y = other.positions;
    for (size_t r = 0; r < runs.size(); ++r) {
      if (found.load(std::memory_order_relaxed)) return;
      if (!runs[r].overlaps(whole)) continue;
      for (size_t f = r * kFaceRun; f < std::min(other.num_faces(), (r + 1) * kFaceRun); ++f) {
        const Tri& t = other.triangles[f];
        // Closed boxes: touching counts, as it does for the exact test.
        const Box3 box = face_box(other, t);
        if (!box.overlaps(whole)) continue;
        bool hit = false;
        grid.for_each_cell(glm::max(box.lo, whole.lo), glm::min(box.hi, whole.hi), [&](const std::vector<int32_t>& faces) {
          for (size_t k = 0; !hit && k < faces.size(); ++k) {
            const Tri& a = candidate.triangles[faces[k]];
            hit = box.overlaps(boxes[faces[k]]) && triangles_intersect(x[a[0]], x[a[1]], x[a[2]], y[t[0]], y[t[1]], y[t[2]]);
          }
        });
        if (hit) {
          found = true;
          return;
        }
      }
    }
  });
  return found;
}

}  // namespace meshquilt
