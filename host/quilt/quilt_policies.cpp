#include "quilt/quilt_policies.h"

#include "spatial/intersecting_pairs.h"

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
  if (others.empty()) return false;
  // One mesh of all parts (element id = part, the candidate is 0), built in place.
  TriMesh joined;
  const auto append = [&](const TriMesh& mesh, int32_t part) {
    const int32_t base = static_cast<int32_t>(joined.positions.size());
    joined.positions.insert(joined.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (const Tri& t : mesh.triangles) {
      joined.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      joined.elements.push_back(part);
    }
  };
  append(candidate, 0);
  for (size_t k = 0; k < others.size(); ++k) append(*others[k], static_cast<int32_t>(k + 1));
  const auto pairs = intersecting_face_pairs(joined, joined.elements, IntersectionScope::different_elements);
  for (const auto& [a, b] : pairs)
    if (joined.elements[a] == 0 || joined.elements[b] == 0) return true;
  return false;
}

}  // namespace meshquilt
