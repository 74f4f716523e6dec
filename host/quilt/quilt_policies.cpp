#include "quilt/quilt_policies.h"

#include <algorithm>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

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
  const auto box_of = [](const TriMesh& mesh, const Tri& t, Vec3& lo, Vec3& hi) {
    lo = hi = mesh.positions[t[0]];
    for (int k = 1; k < 3; ++k) {
      lo = glm::min(lo, mesh.positions[t[k]]);
      hi = glm::max(hi, mesh.positions[t[k]]);
    }
  };
  Vec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  std::vector<Vec3> face_lo(candidate.num_faces()), face_hi(candidate.num_faces());
  double extent = 0.0;
  for (size_t f = 0; f < candidate.num_faces(); ++f) {
    box_of(candidate, candidate.triangles[f], face_lo[f], face_hi[f]);
    low = glm::min(low, face_lo[f]);
    high = glm::max(high, face_hi[f]);
    const Vec3 size = face_hi[f] - face_lo[f];
    extent += std::max({size.x, size.y, size.z});
  }
  BoxGrid grid(std::max(4.0 * extent / static_cast<double>(candidate.num_faces()), 1e-12 * glm::length(high - low) + 1e-300));
  for (size_t f = 0; f < candidate.num_faces(); ++f) grid.insert(static_cast<int32_t>(f), face_lo[f], face_hi[f]);
  const auto overlap = [](const Vec3& a_lo, const Vec3& a_hi, const Vec3& b_lo, const Vec3& b_hi) {
    // Closed boxes: touching counts, as it does for the exact test.
    return a_lo.x <= b_hi.x && b_lo.x <= a_hi.x && a_lo.y <= b_hi.y && b_lo.y <= a_hi.y && a_lo.z <= b_hi.z &&
           b_lo.z <= a_hi.z;
  };
  const auto& x = candidate.positions;
  for (const TriMesh* other : others) {
    for (const Tri& t : other->triangles) {
      Vec3 lo, hi;
      box_of(*other, t, lo, hi);
      if (!overlap(lo, hi, low, high)) continue;
      const auto& y = other->positions;
      bool hit = false;
      grid.for_each_cell(glm::max(lo, low), glm::min(hi, high), [&](const std::vector<int32_t>& faces) {
        for (int32_t f = 0; !hit && f < static_cast<int32_t>(faces.size()); ++f) {
          const int32_t c = faces[f];
          if (!overlap(lo, hi, face_lo[c], face_hi[c])) continue;
          const Tri& a = candidate.triangles[c];
          hit = triangles_intersect(x[a[0]], x[a[1]], x[a[2]], y[t[0]], y[t[1]], y[t[2]]);
        }
      });
      if (hit) return true;
    }
  }
  return false;
}

}  // namespace meshquilt
