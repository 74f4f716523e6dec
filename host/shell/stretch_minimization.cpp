#include "shell/stretch_minimization.h"

#include <algorithm>
#include <glm/matrix.hpp>

#include "stretch_linesearch.h"

namespace meshquilt {

std::vector<std::vector<uint32_t>> independent_batches(const BaseSurface& base, const TextureAtlas& atlas) {
  // A movable (chart-interior) vertex has all its faces in one chart, so its base vertex names it.
  std::vector<int32_t> movable(base.mesh.num_vertices(), -1);
  for (size_t a = 0; a < atlas.vertex_base.size(); ++a)
    if (!atlas.on_boundary[a]) movable[atlas.vertex_base[a]] = static_cast<int32_t>(a);
  std::vector<int32_t> colour(base.mesh.num_vertices(), -1);
  std::vector<std::vector<uint32_t>> batches;
  std::vector<uint8_t> taken;
  for (size_t v = 0; v < movable.size(); ++v) {
    if (movable[v] < 0) continue;
    taken.assign(batches.size() + 1, 0);
    // Vertices sharing a face with v are its edge neighbours.
    for (const auto& [w, length] : base.edges[v])
      if (colour[w] >= 0) taken[colour[w]] = 1;
    const int32_t c = static_cast<int32_t>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    colour[v] = c;
    if (c == static_cast<int32_t>(batches.size())) batches.emplace_back();
    batches[c].push_back(static_cast<uint32_t>(movable[v]));
  }
  return batches;
}

std::vector<glm::dvec2> minimize_stretch(engine::Device& device, const BaseSurface& base,
                                         const TextureAtlas& atlas, const Shell& shell,
                                         const StretchOptions& options) {
  std::vector<glm::dvec2> top = atlas.uv;
  const std::vector<std::vector<uint32_t>> batches = independent_batches(base, atlas);
  if (batches.empty() || options.sweeps <= 0 || !(shell.height > 0.0)) return top;

  // In units of the shell height, so float32 sees tetrahedra of size about 1.
  const double unit = 1.0 / shell.height;
  StretchProblem problem;
  problem.texture_height = 1.0f;
  problem.bottom_uv.reserve(atlas.uv.size());
  for (const glm::dvec2& p : atlas.uv) problem.bottom_uv.emplace_back(p * unit);
  const TriMesh& mesh = base.mesh;
  const size_t faces = mesh.num_faces();
  problem.tets.reserve(3 * faces);
  std::vector<uint32_t> top_count(atlas.uv.size() + 1, 0);
  for (size_t f = 0; f < faces; ++f) {
    const Tri& t = mesh.triangles[f];
    for (const PrismTet& tet : prism_tetrahedra(t)) {
      kernels::stretch_linesearch_layout::StretchTet out{};
      Vec3 s[4];
      for (int k = 0; k < 4; ++k) {
        const int32_t a = atlas.corners[f][tet[k].k];
        out.corners[k] = static_cast<uint32_t>(2 * a + tet[k].top);
        s[k] = shell.corner(t, tet[k], mesh.positions) * unit;
        if (tet[k].top) ++top_count[a + 1];
      }
      const glm::dmat3 edges(s[1] - s[0], s[2] - s[0], s[3] - s[0]);
      // Eq. 9 weights by shell volume, Eq. 8 divides by 3; a flat tet (an invalid prism) keeps a
      // token weight, and the kernel leaves its vertices where they are.
      const double weight = std::max(glm::determinant(edges) / 18.0, 1e-30);
      out.s0 = glm::vec4(glm::vec3(edges[0]), static_cast<float>(weight));
      out.s1 = glm::vec4(glm::vec3(edges[1]), 0.0f);
      out.s2 = glm::vec4(glm::vec3(edges[2]), 0.0f);
      problem.tets.push_back(out);
    }
  }
  for (size_t a = 1; a < top_count.size(); ++a) top_count[a] += top_count[a - 1];
  problem.vertex_tet_offsets = top_count;
  problem.vertex_tets.resize(top_count.back());
  std::vector<uint32_t> fill(top_count.begin(), top_count.end() - 1);
  for (size_t i = 0; i < problem.tets.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      const uint32_t code = problem.tets[i].corners[k];
      if (code & 1u) problem.vertex_tets[fill[code >> 1]++] = static_cast<uint32_t>(i);
    }

  std::vector<glm::vec2> top_uv(problem.bottom_uv);
  StretchLineSearch search(device, problem);
  StretchSearchOptions search_options;
  search_options.sweeps = options.sweeps;
  search_options.seed = options.seed;
  search.run(top_uv, batches, search_options);
  // Vertices that moved take the float result; the rest keep their double positions exactly.
  for (size_t a = 0; a < top.size(); ++a)
    if (top_uv[a] != problem.bottom_uv[a]) top[a] = glm::dvec2(top_uv[a]) / unit;
  return top;
}

}  // namespace meshquilt
