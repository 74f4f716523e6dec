#include "quilt/merging/abutting_elements.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "mesh/disjoint_sets.h"
#include "mesh/topology.h"

namespace meshquilt {
namespace {

// A face's corners as weld representatives, sorted, with the face: equal keys are faces on the
// same three points.
struct FaceKey {
  std::array<int32_t, 3> corners;
  int32_t face;
};

// Whether `b`'s corners are `a`'s in the opposite cyclic order.
bool opposite(const std::array<int32_t, 3>& a, const std::array<int32_t, 3>& b) {
  for (int r = 0; r < 3; ++r)
    if (b[r] == a[0] && b[(r + 1) % 3] == a[2] && b[(r + 2) % 3] == a[1]) return true;
  return false;
}

}  // namespace

int32_t join_abutting_elements(TriMesh& layer, double relative_tolerance, std::vector<int32_t>* kept_vertices) {
  const size_t face_count = layer.num_faces();
  if (face_count == 0 || layer.elements.size() != face_count) return 0;
  // Corners that coincide as inspect's welding would see them (the same clustering).
  const std::vector<int32_t> point = weld_representatives(layer.positions, relative_tolerance);
  const auto corners_of = [&](size_t f) {
    const Tri& t = layer.triangles[f];
    return std::array<int32_t, 3>{point[t[0]], point[t[1]], point[t[2]]};
  };

  // Faces grouped by their lowest corner (a counting sort, linear in the faces), then ordered
  // within each small group.
  std::vector<int32_t> start(layer.positions.size() + 1, 0);
  std::vector<std::array<int32_t, 3>> sorted_corners(face_count);
  for (size_t f = 0; f < face_count; ++f) {
    sorted_corners[f] = corners_of(f);
    std::sort(sorted_corners[f].begin(), sorted_corners[f].end());
    ++start[sorted_corners[f][0] + 1];
  }
  for (size_t v = 0; v < layer.positions.size(); ++v) start[v + 1] += start[v];
  std::vector<FaceKey> keys(face_count);
  for (size_t f = 0; f < face_count; ++f) keys[start[sorted_corners[f][0]]++] = {sorted_corners[f], static_cast<int32_t>(f)};
  const auto key_order = [](const FaceKey& a, const FaceKey& b) {
    return a.corners != b.corners ? a.corners < b.corners : a.face < b.face;
  };
  for (size_t k = 0; k < face_count;) {
    size_t end = k + 1;
    while (end < face_count && keys[end].corners[0] == keys[k].corners[0]) ++end;
    std::sort(keys.begin() + static_cast<std::ptrdiff_t>(k), keys.begin() + static_cast<std::ptrdiff_t>(end), key_order);
    k = end;
  }
  // Exactly two faces on the same points, of different elements, facing each other.
  std::vector<std::pair<int32_t, int32_t>> pairs;
  for (size_t k = 0; k < keys.size();) {
    size_t end = k + 1;
    while (end < keys.size() && keys[end].corners == keys[k].corners) ++end;
    const std::array<int32_t, 3>& c = keys[k].corners;
    if (end - k == 2 && c[0] != c[1] && c[1] != c[2]) {  // sorted: distinct corners
      const int32_t a = keys[k].face, b = keys[k + 1].face;
      if (layer.elements[a] != layer.elements[b] && opposite(corners_of(a), corners_of(b))) pairs.emplace_back(a, b);
    }
    k = end;
  }
  if (pairs.empty()) return 0;

  int32_t element_count = 0;
  for (int32_t e : layer.elements) element_count = std::max(element_count, e + 1);
  DisjointSets groups(static_cast<size_t>(element_count));
  for (const auto& [a, b] : pairs) groups.unite(layer.elements[a], layer.elements[b]);
  std::map<int32_t, std::vector<size_t>> group_pairs;  // group root -> its pairs
  for (size_t p = 0; p < pairs.size(); ++p) group_pairs[groups.find(layer.elements[pairs[p].first])].push_back(p);
  std::vector<std::vector<int32_t>> faces_of(static_cast<size_t>(element_count));
  for (size_t f = 0; f < face_count; ++f) faces_of[layer.elements[f]].push_back(static_cast<int32_t>(f));

  // Each group is joined only if the result is a closed 2-manifold: shared faces removed, the
  // corners of each pair welded.
  DisjointSets welded(layer.positions.size());
  std::vector<uint8_t> removed(face_count, 0), shared(face_count, 0);
  std::vector<int32_t> element_of(static_cast<size_t>(element_count));
  for (int32_t e = 0; e < element_count; ++e) element_of[e] = e;
  int32_t joined = 0;
  for (const auto& [root, members] : group_pairs) {
    SparseDisjointSets weld;  // the corners of this group's pairs
    std::vector<int32_t> elements;
    for (size_t p : members) {
      const auto [a, b] = pairs[p];
      shared[a] = shared[b] = 1;
      elements.push_back(layer.elements[a]);
      elements.push_back(layer.elements[b]);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (point[layer.triangles[a][i]] == point[layer.triangles[b][j]]) {
            weld.unite(layer.triangles[a][i], layer.triangles[b][j]);
          }
    }
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    TriMesh candidate;
    std::map<int32_t, int32_t> local;
    for (int32_t e : elements)
      for (int32_t f : faces_of[e]) {
        if (shared[f]) continue;
        Tri t;
        for (int i = 0; i < 3; ++i) {
          const int32_t v = weld.find(layer.triangles[f][i]);
          const auto [it, fresh] = local.emplace(v, static_cast<int32_t>(candidate.positions.size()));
          if (fresh) candidate.positions.push_back(layer.positions[v]);
          t[i] = it->second;
        }
        candidate.triangles.push_back(t);
      }
    for (size_t p : members) shared[pairs[p].first] = shared[pairs[p].second] = 0;
    if (!inspect_surface(candidate).closed_manifold()) continue;
    for (const auto& [v, to] : weld.joined()) welded.unite(v, to);
    for (size_t p : members) removed[pairs[p].first] = removed[pairs[p].second] = 1;
    for (int32_t e : elements) element_of[e] = elements.front();
    joined += static_cast<int32_t>(elements.size()) - 1;
  }
  if (joined == 0) return 0;
  if (kept_vertices) kept_vertices->clear();

  // Rebuild: surviving faces in order with welded corners, the vertices they use in their old
  // order (the caps' centres, used only by removed faces, go), element ids consecutive in order
  // of first face.
  std::vector<int32_t> vertex_map(layer.positions.size(), -1);
  for (size_t f = 0; f < face_count; ++f)
    if (!removed[f])
      for (int32_t v : layer.triangles[f]) vertex_map[welded.find(v)] = 0;
  TriMesh compact;
  for (size_t v = 0; v < vertex_map.size(); ++v)
    if (vertex_map[v] == 0) {
      vertex_map[v] = static_cast<int32_t>(compact.positions.size());
      compact.positions.push_back(layer.positions[v]);
      if (!layer.origins.empty()) compact.origins.push_back(layer.origins[v]);
      if (kept_vertices) kept_vertices->push_back(static_cast<int32_t>(v));
    }
  std::vector<int32_t> renumbered(static_cast<size_t>(element_count), -1);
  int32_t next_element = 0;
  for (size_t f = 0; f < face_count; ++f) {
    if (removed[f]) continue;
    Tri t;
    for (int i = 0; i < 3; ++i) t[i] = vertex_map[welded.find(layer.triangles[f][i])];
    compact.triangles.push_back(t);
    int32_t& id = renumbered[element_of[layer.elements[f]]];
    if (id < 0) id = next_element++;
    compact.elements.push_back(id);
    if (!layer.sources.empty()) compact.sources.push_back(layer.sources[f]);
  }
  layer = std::move(compact);
  return joined;
}

}  // namespace meshquilt
