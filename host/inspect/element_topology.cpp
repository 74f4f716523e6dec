#include "inspect/element_topology.h"

#include <algorithm>
#include <numeric>

#include <tbb/parallel_sort.h>

#include "mesh/topology.h"
#include "mesh/disjoint_sets.h"

namespace meshquilt {
namespace {

// One undirected edge of one face: the key orders edges, `corner` is the face corner (3f + i)
// where the edge starts, so both endpoint corners are known.
struct EdgeUse {
  uint64_t key;
  int32_t corner;
  bool operator<(const EdgeUse& o) const { return key < o.key || (key == o.key && corner < o.corner); }
};

}  // namespace

ElementTopology element_topology(const TriMesh& mesh) {
  ElementTopology out;
  const size_t nf = mesh.num_faces();
  out.face_element = face_components(mesh, &out.elements);
  std::vector<char> element_bad(out.elements, 0);

  std::vector<EdgeUse> edges(3 * nf);
  for (size_t f = 0; f < nf; ++f) {
    const Tri& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const auto a = static_cast<uint32_t>(t[i]), b = static_cast<uint32_t>(t[(i + 1) % 3]);
      edges[3 * f + i] = {(static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b), static_cast<int32_t>(3 * f + i)};
    }
  }
  tbb::parallel_sort(edges.begin(), edges.end());

  // Corners at one vertex are joined when their faces share an edge at that vertex; the sets
  // left are the vertex's fans.
  DisjointSets fans(3 * nf);
  auto corner_of = [&](int32_t face, int32_t vertex) {
    const Tri& t = mesh.triangles[face];
    return 3 * face + (t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2));
  };
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    const size_t count = j - i;
    const int32_t face0 = edges[i].corner / 3;
    if (count != 2) {
      (count == 1 ? out.boundary_edges : out.nonmanifold_edges) += 1;
      element_bad[out.face_element[face0]] = 1;
    }
    const auto a = static_cast<int32_t>(edges[i].key >> 32), b = static_cast<int32_t>(edges[i].key & 0xffffffffu);
    for (size_t k = i + 1; k < j; ++k) {
      const int32_t face = edges[k].corner / 3;
      fans.unite(corner_of(face0, a), corner_of(face, a));
      fans.unite(corner_of(face0, b), corner_of(face, b));
    }
    i = j;
  }

  std::vector<int32_t> fan_count(mesh.num_vertices(), 0);
  for (size_t c = 0; c < 3 * nf; ++c) {
    if (fans.find(static_cast<int32_t>(c)) == static_cast<int32_t>(c)) ++fan_count[mesh.triangles[c / 3][c % 3]];
  }
  for (size_t c = 0; c < 3 * nf; ++c) {
    const int32_t v = mesh.triangles[c / 3][c % 3];
    if (fan_count[v] > 1) {
      element_bad[out.face_element[c / 3]] = 1;
      fan_count[v] = -fan_count[v];  // count each pinched vertex once
      ++out.nonmanifold_vertices;
    }
  }
  out.element_closed.resize(out.elements);
  for (int32_t e = 0; e < out.elements; ++e) {
    out.element_closed[e] = !element_bad[e];
    out.closed_elements += !element_bad[e];
  }
  return out;
}

}  // namespace meshquilt
