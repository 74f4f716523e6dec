// Planar mesh quilting end to end (Section 2 of the paper) on small swatches: elements stay
// whole, yarns continue across patch seams, chain mail covers the plane, and both back ends make
// the same choices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

#include <glm/common.hpp>

#include "device.h"
#include "core/error.h"
#include "inspect/coverage.h"
#include "inspect/inspect_report.h"
#include "mesh/topology.h"
#include "quilt/planar_quilting.h"
#include "spatial/intersecting_pairs.h"
#include "swatch/chainmail.h"
#include "swatch/fruit.h"
#include "swatch/weave.h"
#include "support/run_cli.h"
#include "support/backends.h"

namespace meshquilt {
namespace {

struct Quality {
  int elements = 0;
  int closed = 0;
  double swatch_side = 0.0;        // the swatch's longer x-y side
  std::vector<double> lengths;     // each element's longer x-y bbox side / swatch_side
  double longest = 0.0;            // the largest of lengths
  double intersecting_share = 0.0; // distinct faces in a pair of different elements / faces
  double coverage = 0.0;
};

Quality measure(const TriMesh& result, const TriMesh& swatch) {
  Quality q;
  InspectOptions options;
  options.plane = true;
  const InspectReport report = inspect_mesh(result, options);
  q.elements = report.elements;
  q.closed = report.closed_elements;
  q.coverage = report.plane->coverage;

  // Independent of inspect: element extents from the output's own element ids.
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : swatch.positions) {
    lo = glm::min(lo, glm::dvec2(p));
    hi = glm::max(hi, glm::dvec2(p));
  }
  q.swatch_side = std::max(hi.x - lo.x, hi.y - lo.y);
  std::map<int32_t, std::pair<glm::dvec2, glm::dvec2>> boxes;
  for (size_t f = 0; f < result.num_faces(); ++f) {
    auto [it, fresh] = boxes.try_emplace(result.elements[f], glm::dvec2(1e300), glm::dvec2(-1e300));
    for (int32_t v : result.triangles[f]) {
      it->second.first = glm::min(it->second.first, glm::dvec2(result.positions[v]));
      it->second.second = glm::max(it->second.second, glm::dvec2(result.positions[v]));
    }
  }
  for (const auto& [e, box] : boxes) {
    q.lengths.push_back(std::max(box.second.x - box.first.x, box.second.y - box.first.y) / q.swatch_side);
    q.longest = std::max(q.longest, q.lengths.back());
  }


  const TriMesh welded = weld_vertices(result);
  const auto pairs = intersecting_face_pairs(welded, face_components(welded), IntersectionScope::different_elements);
  std::set<int32_t> faces;
  for (const auto& [a, b] : pairs) {
    faces.insert(a);
    faces.insert(b);
  }
  q.intersecting_share = static_cast<double>(faces.size()) / welded.num_faces();
  return q;
}

TriMesh quilt(const TriMesh& swatch, double size, QuiltStats* stats, engine::BackendChoice backend = engine::BackendChoice::cpu) {
  auto device = engine::open_device(backend);
  PlanarQuiltOptions options;
  options.width = options.height = size;
  options.seed = 7;
  return quilt_plane(swatch, *device, options, stats);
}

// Four rows of rings so the swatch holds two vertical periods: with half-swatch sub-patches the
// candidate translations then span a whole period in both directions. 1,440 faces.
ChainmailOptions test_chainmail() {
  ChainmailOptions options;
  options.rows = 4;
  options.columns = 3;
  options.ring_segments = 12;
  options.wire_segments = 5;
  return options;
}

TEST(PlanarQuilting, WeaveYarnsContinueAcrossSeams) {
  const TriMesh swatch = make_weave(WeaveOptions::small());
  QuiltStats stats;
  const TriMesh result = quilt(swatch, 4.0, &stats);
  const Quality q = measure(result, swatch);
  EXPECT_GE(q.longest, 2.5);
  EXPECT_GE(q.closed, 0.98 * q.elements);
  EXPECT_LE(q.intersecting_share, 0.001);
  EXPECT_GT(stats.merges.stitched, 0);
  EXPECT_LE(stats.dropped_elements, 0.01 * q.elements);
}

// The faces of `mesh` whose per-face label says they belong to one yarn direction.
TriMesh faces_where(const TriMesh& mesh, const std::vector<int32_t>& label, bool (*keep)(int32_t, int32_t),
                    int32_t warps) {
  TriMesh part;
  part.positions = mesh.positions;
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    if (keep(label[f], warps)) {
      part.triangles.push_back(mesh.triangles[f]);
      part.elements.push_back(mesh.elements[f]);
    }
  return part;
}

// Each yarn direction on its own covers the plane at the scale of the swatch's own gaps: a place
// where only warps remain (a weft segment lost at a seam) is a gap in the wefts' coverage. The
// plane asked for is the measure; the output's own body (2nd-98th percentiles of its faces)
// also holds the yarn ends that hang past the plane's edge by differing lengths.
TEST(PlanarQuilting, TwillCoversThePlaneInEachYarnDirection) {
  WeaveOptions weave = WeaveOptions::small();
  weave.pattern = twill_pattern(2, 3);
  const TriMesh swatch = make_weave(weave);
  const int32_t warps = weave_yarn_counts(weave).x;
  QuiltStats stats;
  const TriMesh result = quilt(swatch, 4.0, &stats);
  const Quality q = measure(result, swatch);
  EXPECT_EQ(q.closed, q.elements);
  EXPECT_EQ(q.intersecting_share, 0.0);
  ASSERT_EQ(result.sources.size(), result.num_faces());
  // The plane asked for: 4 x 4 swatches from the origin (the twill swatch is square).
  EXPECT_NEAR(stats.plane_extent.x, 4.0 * q.swatch_side, 1e-9);
  EXPECT_NEAR(stats.plane_extent.y, 4.0 * q.swatch_side, 1e-9);
  PlaneCoverageOptions no_margin;
  no_margin.margin = 0.0;
  const auto is_warp = [](int32_t source, int32_t n) { return source < n; };
  const auto is_weft = [](int32_t source, int32_t n) { return source >= n; };
  for (const auto& [name, keep] : {std::pair{"warps", +is_warp}, std::pair{"wefts", +is_weft}}) {
    const TriMesh swatch_part = faces_where(swatch, swatch.elements, keep, warps);
    const TriMesh part = faces_where(result, result.sources, keep, warps);
    const double cell = self_covering_cell(swatch_part, q.swatch_side);
    const double body = plane_coverage(plane_body(part), cell, no_margin).coverage;
    PlaneCoverageOptions asked;
    asked.region = {glm::dvec2(0.0), stats.plane_extent};
    const double coverage = plane_coverage(part, cell, asked).coverage;
    std::printf("twill %s: coverage %.4f of the plane, %.4f of the output's body, on cells of %.3f\n", name,
                coverage, body, cell);
    EXPECT_GE(coverage, 0.99) << name;  // measured: warps 1.0, wefts 0.997
    EXPECT_GE(body, 0.98) << name;      // measured: 0.985 each
  }
}

// The sparse crimped wire mesh (n wires a direction): wires continue across seams, so the 4 x 4
// plane holds few wires (8n would be ideal: every wire one element across the plane), most of
// them several swatch lengths long.
TEST(PlanarQuilting, SparseWiresContinueAcrossThePlane) {
  const WeaveOptions wire = WeaveOptions::small_wire();
  const TriMesh swatch = make_weave(wire);
  const int n = weave_yarn_counts(wire).x;
  QuiltStats stats;
  const TriMesh result = quilt(swatch, 4.0, &stats);
  const Quality q = measure(result, swatch);
  EXPECT_EQ(q.closed, q.elements);
  EXPECT_EQ(q.intersecting_share, 0.0);
  EXPECT_GE(q.coverage, 0.98);
  EXPECT_LE(q.elements, 1.25 * 8 * n);
  std::vector<double> lengths = q.lengths;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double median_length = lengths[lengths.size() / 2];
  std::printf("sparse wire: %d wires (n = %d), median %.2f swatch lengths, %d bridged\n", q.elements, n, median_length,
              stats.merges.bridged);
  EXPECT_GE(median_length, 3.0);
}

// Sparse fruit whose rows drift from patch to patch: with seed 3 the lowest row's centres fall
// on the plane's lower edge, where the centre rule alone leaves a band of the plane bare.
// Patches seeded again there place the fruit up to a quarter of a fruit past the edge.
TEST(PlanarQuilting, FruitRowsReachThePlanesEdge) {
  FruitOptions fruit = FruitOptions::small();
  fruit.seed = 3;
  const TriMesh swatch = make_fruit(fruit);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  PlanarQuiltOptions options;
  options.width = options.height = 4.0;
  options.seed = 3;
  QuiltStats stats;
  const TriMesh result = quilt_plane(swatch, *device, options, &stats);
  const Quality q = measure(result, swatch);
  EXPECT_EQ(q.closed, q.elements);
  EXPECT_EQ(q.intersecting_share, 0.0);
  // Element-scale cells, as inspect sizes them: half the median element's x-y extent.
  std::vector<double> lengths = q.lengths;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  PlaneCoverageOptions asked;
  asked.region = {glm::dvec2(0.0), stats.plane_extent};
  const double coverage = plane_coverage(result, 0.5 * lengths[lengths.size() / 2] * q.swatch_side, asked).coverage;
  std::printf("fruit seed 3: %d fruit, %d holes, coverage %.4f of the plane\n", q.elements, stats.holes, coverage);
  EXPECT_GE(coverage, 0.98);  // measured: 0.997
  EXPECT_EQ(stats.holes, 0);
}

TEST(PlanarQuilting, ChainMailStaysWholeAndCovers) {
  const TriMesh swatch = make_chainmail(test_chainmail());
  QuiltStats stats;
  const TriMesh result = quilt(swatch, 4.0, &stats);
  const Quality q = measure(result, swatch);
  EXPECT_GE(q.closed, 0.98 * q.elements);
  EXPECT_LE(q.intersecting_share, 0.001);
  EXPECT_GE(q.coverage, 0.98);
  // Overlapping patches' twin rings are one ring: filled once, found as lattice copies, or merged.
  EXPECT_GT(stats.filled_elements + stats.merges.stitched + stats.merges.replaced + stats.merges.lattice_copies, 0);
  EXPECT_LE(stats.dropped_elements, 0.01 * q.elements);
  // 4 x 4 swatch extents hold far more rings than one swatch.
  EXPECT_GT(q.elements, 8 * 12);
}

TEST(PlanarQuilting, SameSeedSameOutputOtherSeedOther) {
  const TriMesh swatch = make_chainmail(test_chainmail());
  auto device = engine::open_device(engine::BackendChoice::cpu);
  PlanarQuiltOptions options;
  options.width = options.height = 2.0;
  options.seed = 3;
  options.fill_margin = 0.0;  // a filled pattern has no choice to make
  const TriMesh a = quilt_plane(swatch, *device, options);
  const TriMesh b = quilt_plane(swatch, *device, options);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  options.seed = 4;
  const TriMesh c = quilt_plane(swatch, *device, options);
  EXPECT_NE(a.positions, c.positions);
}

TEST(PlanarQuilting, VulkanAndCpuGiveTheSameOutputFiles) {
  {
    std::string why;
    const auto vulkan = test::open_backend(engine::Backend::vulkan, &why);
    MESHQUILT_REQUIRE_DEVICE(vulkan, why);
  }
  const auto dir = test::scratch_dir("backend_parity");
  const auto swatch = dir / "chain.ply";
  ASSERT_EQ(test::run_cli("swatch chainmail --preset small -o '" + swatch.string() + "'").exit_code, 0);
  std::string files[2];
  const char* backends[2] = {"cpu", "vulkan"};
  for (int k = 0; k < 2; ++k) {
    const auto out = dir / (std::string(backends[k]) + ".ply");
    const auto stats = dir / (std::string(backends[k]) + ".json");
    const test::CliResult r = test::run_cli("synth --swatch '" + swatch.string() + "' --plane 2x2 --seed 5 --fill-margin 0 --progress none --backend " +
                                            backends[k] + " --stats '" + stats.string() + "' -o '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    files[k] = test::read_file(out);
    const std::string json = test::read_file(stats);
    for (const char* key : {"\"faces\"", "\"vertices\"", "\"elements\"", "\"seconds\"", "\"backend\"", "\"seed\"",
                            "\"stages\"", "\"dropped_elements\"", "\"index\"", "\"swatch\"", "\"match\""})
      EXPECT_NE(json.find(key), std::string::npos) << key;
    EXPECT_NE(json.find(std::string("\"backend\": \"") + backends[k] + "\""), std::string::npos) << json;
  }
  EXPECT_GT(files[0].size(), 1000u);
  EXPECT_TRUE(files[0] == files[1]) << "the back ends chose differently";
}

TEST(SynthCli, ProgressAsJsonLines) {
  const auto dir = test::scratch_dir("progress_json");
  const auto swatch = dir / "chain.ply";
  ASSERT_EQ(test::run_cli("swatch chainmail --preset small -o '" + swatch.string() + "'").exit_code, 0);
  const test::CliResult r = test::run_cli("synth --swatch '" + swatch.string() +
                                          "' --plane 1x1 --backend cpu --progress json -o '" + (dir / "o.obj").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("{\"event\":\"progress\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("{\"event\":\"done\""), std::string::npos) << r.output;
  // OBJ output keeps element ids as groups.
  EXPECT_NE(test::read_file(dir / "o.obj").find("g element_0"), std::string::npos);
}

// The nearest-face grid is written to $MESHQUILT_CACHE by the first job and read by the next:
// the stats say so, and the outputs are the same file as with no cache.
TEST(SynthCli, AGridKeptInTheCacheGivesTheSameOutput) {
  const auto dir = test::scratch_dir("grid_cache");
  const auto swatch = dir / "chain.ply";
  ASSERT_EQ(test::run_cli("swatch chainmail --preset small -o '" + swatch.string() + "'").exit_code, 0);
  const char* before = std::getenv("MESHQUILT_CACHE");
  const std::string saved = before ? before : "";
  std::string files[3];
  const char* caches[3] = {"cache", "cache", "off"};
  const char* sources[3] = {"written", "read", "built"};
  for (int k = 0; k < 3; ++k) {
    ::setenv("MESHQUILT_CACHE", k < 2 ? (dir / caches[k]).c_str() : caches[k], 1);
    const auto out = dir / ("out" + std::to_string(k) + ".ply");
    const auto stats = dir / ("stats" + std::to_string(k) + ".json");
    const test::CliResult r = test::run_cli("synth --swatch '" + swatch.string() + "' --plane 1x1 --seed 3 --progress none --backend cpu --stats '" +
                                            stats.string() + "' -o '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    files[k] = test::read_file(out);
    EXPECT_NE(test::read_file(stats).find(std::string("\"grid\": \"") + sources[k] + "\""), std::string::npos)
        << test::read_file(stats);
  }
  if (before) ::setenv("MESHQUILT_CACHE", saved.c_str(), 1); else ::unsetenv("MESHQUILT_CACHE");
  EXPECT_GT(files[0].size(), 1000u);
  EXPECT_TRUE(files[0] == files[1] && files[1] == files[2]) << "a grid from the cache changed the output";
}

}  // namespace
}  // namespace meshquilt
