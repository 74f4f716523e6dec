#include "quilt/broken_elements.h"

#include <algorithm>
#include <map>

#include "mesh/topology.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {

BrokenElements remove_broken_elements(const std::vector<const TriMesh*>& elements, bool swatch_closed,
                                      bool swatch_unfolded, std::vector<uint8_t>& alive,
                                      const FaceIntersections* known) {
  BrokenElements removed;
  std::vector<size_t> candidates;
  for (size_t i = 0; i < elements.size(); ++i)
    if (alive[i]) candidates.push_back(i);
  for (size_t i : candidates) {
    if (swatch_closed && !inspect_surface(*elements[i]).closed_manifold()) {
      alive[i] = 0;
      ++removed.open;
    }
  }
  std::vector<size_t> part_of;
  std::vector<int32_t> face_part;
  for (size_t i : candidates)
    if (alive[i]) {
      face_part.insert(face_part.end(), elements[i]->num_faces(), static_cast<int32_t>(part_of.size()));
      part_of.push_back(i);
    }
  const auto test = [&] {
    TriMesh joined;
    for (size_t i : part_of) {
      const auto first = static_cast<int32_t>(joined.positions.size());
      joined.positions.insert(joined.positions.end(), elements[i]->positions.begin(), elements[i]->positions.end());
      for (const Tri& t : elements[i]->triangles) joined.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
    }
    return find_intersecting_faces(joined, face_part);
  };
  const FaceIntersections found = known && removed.open == 0 ? *known : test();
  if (swatch_unfolded) {
    for (const auto& [a, b] : found.same_element) {
      const size_t i = part_of[face_part[a]];
      if (alive[i]) {
        alive[i] = 0;
        ++removed.folded;
      }
    }
  }
  const std::vector<FacePair>& pairs = found.different_elements;
  removed.intersecting_face_pairs = static_cast<int>(pairs.size());
  std::map<std::pair<int32_t, int32_t>, int> element_pairs;
  for (const auto& [a, b] : pairs) ++element_pairs[std::minmax(face_part[a], face_part[b])];
  // Fewest drops: repeatedly remove the element that passes through the most live others (ties:
  // fewer faces, then the later one), so one bad element does not take its neighbours with it.
  std::vector<std::vector<size_t>> partners(elements.size());
  for (const auto& [pair, count] : element_pairs) {
    partners[part_of[pair.first]].push_back(part_of[pair.second]);
    partners[part_of[pair.second]].push_back(part_of[pair.first]);
  }
  while (true) {
    size_t worst = elements.size();
    size_t worst_count = 0;
    for (size_t i = 0; i < elements.size(); ++i) {
      if (!alive[i]) continue;
      size_t count = 0;
      for (size_t j : partners[i]) count += alive[j];
      if (count == 0) continue;
      const bool better = count > worst_count ||
                          (count == worst_count && elements[i]->num_faces() <= elements[worst]->num_faces());
      if (better) {
        worst = i;
        worst_count = count;
      }
    }
    if (worst == elements.size()) break;
    alive[worst] = 0;
    ++removed.intersecting;
  }
  return removed;
}

}  // namespace meshquilt
