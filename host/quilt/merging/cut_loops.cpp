#include "quilt/merging/cut_loops.h"

#include <algorithm>
#include <unordered_map>

namespace meshquilt {

bool cut_loops(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& neighbors,
               const std::vector<uint8_t>& keep, std::vector<CutLoop>& loops, std::string* why) {
  loops.clear();
  // Outgoing boundary half-edges per vertex: (face, slot, is_cut).
  struct Out {
    int32_t face, slot;
    bool cut;
  };
  std::unordered_map<int32_t, std::vector<Out>> out;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!keep[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const int32_t g = neighbors[f][k];
      const bool cut = g >= 0 && !keep[g];
      if (g == -1 || cut) out[mesh.triangles[f][k]].push_back({static_cast<int32_t>(f), k, cut});
      if (g == -2) {
        if (why) *why = "kept face " + std::to_string(f) + " has a non-manifold edge";
        return false;
      }
    }
  }
  for (const auto& [v, list] : out)
    if (list.size() > 1) {
      if (why) *why = "the kept region is pinched at vertex " + std::to_string(v);
      return false;
    }
  std::unordered_map<int32_t, uint8_t> used;
  for (const auto& [start, list] : out) {
    if (used[start]) continue;
    CutLoop loop;
    bool any_cut = false, any_original = false;
    int32_t v = start;
    while (!used[v]) {
      used[v] = 1;
      const Out& o = out.at(v).front();
      loop.vertices.push_back(v);
      loop.faces.push_back(o.face);
      (o.cut ? any_cut : any_original) = true;
      v = mesh.triangles[o.face][(o.slot + 1) % 3];
      if (!out.count(v)) {
        if (why) *why = "a boundary chain ends at vertex " + std::to_string(v);
        return false;
      }
    }
    if (v != start) {
      if (why) *why = "boundary chains merge at vertex " + std::to_string(v);
      return false;
    }
    if (any_cut && any_original) {
      if (why) *why = "a cut loop runs along the element's own boundary";
      return false;
    }
    if (any_cut) loops.push_back(std::move(loop));
  }
  // Deterministic order: by smallest vertex index.
  std::sort(loops.begin(), loops.end(), [](const CutLoop& x, const CutLoop& y) {
    return *std::min_element(x.vertices.begin(), x.vertices.end()) <
           *std::min_element(y.vertices.begin(), y.vertices.end());
  });
  return true;
}

int32_t tidy_cut(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& neighbors,
                 std::vector<uint8_t>& keep) {
  int32_t removed = 0;
  const size_t F = mesh.num_faces();
  for (int pass = 0; pass < 64; ++pass) {
    bool changed = false;
    for (size_t f = 0; f < F; ++f) {
      if (!keep[f]) continue;
      int cuts = 0;
      for (int k = 0; k < 3; ++k) cuts += neighbors[f][k] >= 0 && !keep[neighbors[f][k]];
      if (cuts >= 2) keep[f] = 0, ++removed, changed = true;
    }
    std::unordered_map<int32_t, int32_t> outgoing;
    for (size_t f = 0; f < F; ++f) {
      if (!keep[f]) continue;
      for (int k = 0; k < 3; ++k)
        if (neighbors[f][k] == -1 || (neighbors[f][k] >= 0 && !keep[neighbors[f][k]])) ++outgoing[mesh.triangles[f][k]];
    }
    for (size_t f = 0; f < F; ++f) {
      if (!keep[f]) continue;
      for (int k = 0; k < 3; ++k) {
        auto it = outgoing.find(mesh.triangles[f][k]);
        if (it != outgoing.end() && it->second > 1) {
          keep[f] = 0, ++removed, changed = true;
          break;
        }
      }
    }
    if (!changed) break;
  }
  return removed;
}

}  // namespace meshquilt
