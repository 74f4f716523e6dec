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

bool passes_through(const TriMesh& candidate, const std::vector<const TriMesh*>& others) {
  if (others.empty() || candidate.num_faces() == 0) return false;
  // Only candidate-against-other pairs are tested, through a hash of the candidate's faces
  // (cells about four faces across), and the first intersection ends the search.
  const auto box_of = [](const TriMesh& mesh, const Tri& t) {
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    return Box3{glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)};
  };
  Box3 whole;
  std::vector<Box3> boxes(candidate.num_faces());
  double extent = 0.0;
  for (size_t f = 0; f < candidate.num_faces(); ++f) {
    boxes[f] = box_of(candidate, candidate.triangles[f]);
    whole = {glm::min(whole.lo, boxes[f].lo), glm::max(whole.hi, boxes[f].hi)};
    const Vec3 size = boxes[f].extent();
    extent += std::max({size.x, size.y, size.z});
  }
  BoxGrid grid(std::max(4.0 * extent / static_cast<double>(candidate.num_faces()),
                        1e-12 * glm::length(whole.extent()) + 1e-300));
  for (size_t f = 0; f < candidate.num_faces(); ++f) grid.insert(static_cast<int32_t>(f), boxes[f].lo, boxes[f].hi);
  const auto& x = candidate.positions;
  // The others are searched side by side; any hit ends every search (the answer is the same
  // whichever finds it).
  std::atomic<bool> found{false};
  tbb::parallel_for(size_t{0}, others.size(), [&](size_t o) {
    const TriMesh& other = *others[o];
    const auto& y = other.positions;
    for (const Tri& t : other.triangles) {
      if (found.load(std::memory_order_relaxed)) return;
      // Closed boxes: touching counts, as it does for the exact test.
      const Box3 box = box_of(other, t);
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
  });
  return found;
}

}  // namespace meshquilt
