// `--provenance`: every output vertex names the swatch vertex it was copied from. Checked against
// the swatch file itself: a face's three named vertices are a face of the swatch, in its order
// (all but faces at seams, which use vertices welded from the other copy: 8% of the small weave's
// faces over a 2 x 2 plane, where yarns are short; scrambled origins would give almost none), the named
// vertex belongs to the swatch element the face came from (where nothing was stitched: `source` is per
// element), and elements that were only moved are the swatch's vertices translated.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "shell/texture_file.h"
#include "support/run_cli.h"

namespace meshquilt::test {
namespace {

// Per swatch vertex, its element as synth numbers sources: the rank of its face's element id
// (the PLY `element` property, else the connected component).
std::vector<int32_t> vertex_elements(const TriMesh& swatch) {
  const std::vector<int32_t> labels = swatch.elements.empty() ? face_components(swatch) : swatch.elements;
  std::vector<int32_t> ids(labels);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<int32_t> of(swatch.num_vertices(), -1);
  for (size_t f = 0; f < swatch.num_faces(); ++f)
    for (int32_t v : swatch.triangles[f])
      of[v] = static_cast<int32_t>(std::lower_bound(ids.begin(), ids.end(), labels[f]) - ids.begin());
  return of;
}

// Counts vertices whose origin is not a vertex of a source of one of their faces; and, per output
// element, whether it is its origins' swatch positions translated (to 1e-9 of the swatch's size).
struct Check {
  size_t vertices = 0, foreign = 0, elements = 0, translated = 0, faces = 0, swatch_faces = 0;
};

Check check(const TriMesh& out, const TriMesh& swatch) {
  const std::vector<int32_t> swatch_element = vertex_elements(swatch);
  std::vector<std::set<int32_t>> sources(out.num_vertices());
  for (size_t f = 0; f < out.num_faces(); ++f)
    for (int32_t v : out.triangles[f]) sources[v].insert(out.sources[f]);
  Check c;
  c.vertices = out.num_vertices();
  std::set<std::array<int32_t, 3>> swatch_faces;
  for (const Tri& t : swatch.triangles) {
    swatch_faces.insert({t[0], t[1], t[2]});
    swatch_faces.insert({t[1], t[2], t[0]});
    swatch_faces.insert({t[2], t[0], t[1]});
  }
  c.faces = out.num_faces();
  for (const Tri& t : out.triangles)
    c.swatch_faces += swatch_faces.count({out.origins[t[0]], out.origins[t[1]], out.origins[t[2]]});
  EXPECT_EQ(out.origins.size(), out.num_vertices());
  for (size_t v = 0; v < out.origins.size(); ++v) {
    const int32_t o = out.origins[v];
    if (o < 0 || o >= static_cast<int32_t>(swatch.num_vertices()) || !sources[v].count(swatch_element[o]))
      ++c.foreign;
  }
  std::map<int32_t, std::vector<int32_t>> vertices_of;
  for (size_t f = 0; f < out.num_faces(); ++f)
    for (int32_t v : out.triangles[f]) vertices_of[out.elements[f]].push_back(v);
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : swatch.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double size = glm::length(hi - lo);
  for (auto& [e, vs] : vertices_of) {
    ++c.elements;
    const Vec3 offset = out.positions[vs[0]] - swatch.positions[out.origins[vs[0]]];
    const bool moved_only = std::all_of(vs.begin(), vs.end(), [&](int32_t v) {
      return glm::length(out.positions[v] - swatch.positions[out.origins[v]] - offset) < 1e-9 * size;
    });
    c.translated += moved_only;
  }
  return c;
}

TEST(Provenance, PlanarChainMailVerticesNameTheirSwatchVertices) {
  const auto dir = scratch_dir("provenance_plane");
  ASSERT_EQ(run_cli("swatch chainmail --rows 4 --columns 4 --ring-segments 16 --wire-segments 6 -o '" +
                    (dir / "mail.ply").string() + "'")
                .exit_code,
            0);
  const CliResult r =
      run_cli("synth --progress none --backend cpu --plane 3x3 --swatch '" + (dir / "mail.ply").string() +
              "' --provenance -o '" + (dir / "out.ply").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Check c = check(read_mesh(dir / "out.ply"), read_mesh(dir / "mail.ply"));
  EXPECT_EQ(c.foreign, 0u) << c.vertices;
  EXPECT_EQ(c.swatch_faces, c.faces);
  // The swatch lies flat in its own frame, so a copy only translated keeps its shape exactly.
  EXPECT_GT(c.translated, c.elements / 2) << c.elements;
  // Without the flag the output has no `origin` property.
  ASSERT_EQ(run_cli("synth --progress none --backend cpu --plane 3x3 --swatch '" +
                    (dir / "mail.ply").string() + "' -o '" + (dir / "plain.ply").string() + "'")
                .exit_code,
            0);
  EXPECT_TRUE(read_mesh(dir / "plain.ply").origins.empty());
}

TEST(Provenance, StitchedYarnsAndTheTextureFileKeepThem) {
  const auto dir = scratch_dir("provenance_weave");
  ASSERT_EQ(run_cli("swatch weave --preset small -o '" + (dir / "weave.ply").string() + "'").exit_code, 0);
  const CliResult r = run_cli("synth --progress none --backend cpu --plane 2x2 --swatch '" +
                              (dir / "weave.ply").string() + "' --provenance --stats '" +
                              (dir / "s.json").string() + "' -o '" + (dir / "out.ply").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_file(dir / "s.json").find("\"stitched_pairs\": 0"), std::string::npos)
      << "nothing was stitched";
  const TriMesh out = read_mesh(dir / "out.ply");
  const Check c = check(out, read_mesh(dir / "weave.ply"));
  EXPECT_GT(c.swatch_faces, 0.85 * static_cast<double>(c.faces)) << c.faces;
  EXPECT_LT(c.swatch_faces, c.faces) << "no seam fans: nothing was stitched";
  // The texture file of a curved job keeps what the mesh says.
  ASSERT_EQ(run_cli("synth --progress none --backend cpu --base '" + std::string(MESHQUILT_SOURCE_DIR) +
                    "/data/sphere.off' --scale 0.4 --max-patches 4 --swatch '" +
                    (dir / "weave.ply").string() + "' --provenance --write-texture '" +
                    (dir / "t.mqt").string() + "' -o '" + (dir / "sphere.ply").string() + "'")
                .exit_code,
            0);
  const TriMesh sphere = read_mesh(dir / "sphere.ply");
  EXPECT_EQ(read_texture_file(dir / "t.mqt").origins, sphere.origins);
  EXPECT_GT(check(sphere, read_mesh(dir / "weave.ply")).swatch_faces,
            0.85 * static_cast<double>(sphere.num_faces()));
}

}  // namespace
}  // namespace meshquilt::test
