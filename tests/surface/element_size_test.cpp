// Rings the size asked over scanned bases (#65's job: the 6 x 5 mail of 16 x 6 segments at scale
// 0.08): the median ring, measured from the output alone by `inspect --rings` (centre lines, not
// the layout), near the radius the scale asks, the stats' own measure of whole copies agreeing,
// the mail one linked piece, and the cones the stats list on the base with indices that sum as
// the base's topology asks. The layout's own median left these bases' median ring 7-8% small;
// laid out again by the filled rings' median it is within 5% (decision 0058); the cone metric's
// pairs of cones keep p10 and p90 near #65's bars (0060).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>
#include <string>

#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include "mesh/mesh_io.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

// #65's job with a swatch (`swatch SWATCH_ARGS`) over a base at scale 0.08 (and SYNTH_ARGS),
// inspected with INSPECT_ARGS: inspect's JSON report and synth's stats.
struct Job {
  nlohmann::json report, stats;
};

void run_job(const std::filesystem::path& dir, const std::string& swatch_args, const std::filesystem::path& base,
             const std::string& inspect_args, Job* job, const std::string& synth_args = "") {
  const auto swatch = dir / "swatch.ply", out = dir / "out.ply", stats = dir / "stats.json";
  const auto made = test::run_cli("swatch " + swatch_args + " -o '" + swatch.string() + "'");
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const auto run = test::run_cli("synth --swatch '" + swatch.string() + "' --base '" + base.string() +
                                 "' --scale 0.08 --backend cpu --progress none " + synth_args + " --stats '" +
                                 stats.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto inspect = test::run_cli("inspect '" + out.string() + "' " + inspect_args + " --swatch '" +
                                     swatch.string() + "' --base '" + base.string() + "' --json 2>/dev/null");
  ASSERT_EQ(inspect.exit_code, 0) << inspect.output;
  job->report = nlohmann::json::parse(inspect.output);
  job->stats = nlohmann::json::parse(test::read_file(stats));
}

class ElementSize : public ::testing::TestWithParam<const char*> {};

TEST_P(ElementSize, TheMedianRingIsTheSizeAsked) {
  const auto base = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes" / GetParam();
  if (!std::filesystem::exists(base)) GTEST_SKIP() << base << " not found";
  const auto dir = test::scratch_dir(std::string("element_size_") + GetParam());
  Job job;
  ASSERT_NO_FATAL_FAILURE(
      run_job(dir, "chainmail --rows 6 --columns 5 --ring-segments 16 --wire-segments 6", base, "--rings --scale 0.08", &job));
  const nlohmann::json& rings = job.report.at("rings");
  const nlohmann::json over = rings.at("radius_over_asked");
  const nlohmann::json& size = job.stats.at("element_size");
  std::printf("%s: radius over asked %.3f / %.3f / %.3f, stats %.3f / %.3f / %.3f, linked to >= 3 %.3f, piece %.3f\n",
              GetParam(), over.at("p10").get<double>(), over.at("median").get<double>(), over.at("p90").get<double>(),
              size.at("p10").get<double>(), size.at("median").get<double>(), size.at("p90").get<double>(),
              rings.at("linked_to_3_share").get<double>(), rings.at("largest_piece_share").get<double>());
  EXPECT_NEAR(over.at("median").get<double>(), 1.0, 0.05);
  // Pairs of cones where the layout's scale ran away (decision 0060): without them p90 was 1.48
  // on the bunny and 1.46 on spot, p10 0.50 on the bust.
  EXPECT_LE(over.at("p90").get<double>(), 1.30);
  EXPECT_GE(over.at("p10").get<double>(), 0.70);
  EXPECT_NEAR(size.at("median").get<double>(), over.at("median").get<double>(), 0.03);
  // The bust's layout alone leaves the median ring small; it is laid out again by the fill's.
  if (std::string(GetParam()) == "decimated-max.obj") EXPECT_GT(job.stats.at("size_correction").get<double>(), 1.02);
  EXPECT_GE(rings.at("linked_to_3_share").get<double>(), 0.93);
  EXPECT_GE(rings.at("largest_piece_share").get<double>(), 0.95);

  // Each cone the stats name lies on one of the base's faces, in the base's units.
  const nlohmann::json& report = job.stats;
  const nlohmann::json& cones = report.at("cone_points");
  EXPECT_EQ(cones.size(), report.at("cones").get<size_t>());
  // Poincare-Hopf over these closed genus-0 bases: the indices sum to 2 in whole turns.
  const auto indices = report.at("cone_indices").get<std::vector<int>>();
  EXPECT_EQ(indices.size(), cones.size());
  int sum = 0;
  for (int k : indices) sum += k;
  EXPECT_EQ(sum, 2 * report.at("field_symmetry").get<int>());
  const TriMesh mesh = read_mesh(base);
  for (const auto& c : cones) {
    const Vec3 p(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
    double nearest = 1e300;
    for (const Tri& t : mesh.triangles) {
      const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], d = mesh.positions[t[2]];
      const Vec3 n = glm::cross(b - a, d - a);
      const double twice_area = glm::length(n);
      if (!(twice_area > 0.0)) continue;
      // Barycentric coordinates of p's projection, and its height over the face's plane.
      const double u = glm::dot(glm::cross(d - b, p - b), n) / (twice_area * twice_area);
      const double v = glm::dot(glm::cross(a - d, p - d), n) / (twice_area * twice_area);
      if (u < -1e-6 || v < -1e-6 || u + v > 1.0 + 1e-6) continue;
      nearest = std::min(nearest, std::abs(glm::dot(p - a, n)) / twice_area);
    }
    EXPECT_LT(nearest, 1e-6 * report.at("shell_height").get<double>() / report.at("shell_height_share").get<double>())
        << c.dump();
  }
  std::filesystem::remove_all(dir);
}

// --size-hold trades shape for size: held at 10, the bunny's rings come within #65's size bars
// but p10's 0.80 (the price, oval rings, is printed: decision 0056). Brought to the size asked
// by the stats' measure (radius of gyration, which an oval's centre line falls short of: 2.7%
// here), p10 of the centre lines is 0.79 (decision 0058).
TEST(SizeHold, EvensTheRingsOverTheBunny) {
  const auto base = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes/bunny.off";
  if (!std::filesystem::exists(base)) GTEST_SKIP() << base << " not found";
  const auto dir = test::scratch_dir("element_size_hold");
  Job job;
  ASSERT_NO_FATAL_FAILURE(run_job(dir, "chainmail --rows 6 --columns 5 --ring-segments 16 --wire-segments 6", base,
                                  "--rings --scale 0.08", &job, "--size-hold 10"));
  const nlohmann::json& rings = job.report.at("rings");
  const nlohmann::json& over = rings.at("radius_over_asked");
  std::printf("bunny held at 10: radius over asked %.3f / %.3f / %.3f, aspect %.2f, linked to >= 3 %.3f, piece %.3f\n",
              over.at("p10").get<double>(), over.at("median").get<double>(), over.at("p90").get<double>(),
              rings.at("median_aspect").get<double>(), rings.at("linked_to_3_share").get<double>(),
              rings.at("largest_piece_share").get<double>());
  EXPECT_GE(over.at("p10").get<double>(), 0.78);
  EXPECT_LE(over.at("p90").get<double>(), 1.25);
  EXPECT_NEAR(over.at("median").get<double>(), 1.0, 0.05);
  EXPECT_NEAR(job.stats.at("element_size").at("median").get<double>(), 1.0, 0.02);
  EXPECT_GE(rings.at("linked_to_3_share").get<double>(), 0.93);
  EXPECT_GE(rings.at("largest_piece_share").get<double>(), 0.95);
  std::filesystem::remove_all(dir);
}

// bunny.off's ears: its faces above this height (y up), and how much of them a weave covers.
constexpr double kEarsAbove = 0.14;
constexpr double kEarCoverage = 0.95;

// #65's weave: the default plain weave over the bunny at the same scale still runs on across
// patches, and no yarn leaves the shell (the base to the shell height above it) by more than its
// own radius.
TEST(WeaveOverABase, YarnsContinueAndStayInTheShell) {
  const auto base = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes/bunny.off";
  if (!std::filesystem::exists(base)) GTEST_SKIP() << base << " not found";
  const auto dir = test::scratch_dir("element_size_weave");
  Job job;
  ASSERT_NO_FATAL_FAILURE(run_job(dir, "weave", base, "--yarns", &job));
  const nlohmann::json& report = job.report;
  const nlohmann::json& synth = job.stats;
  const double shell = synth.at("shell_height").get<double>();
  const double diagonal = shell / synth.at("shell_height_share").get<double>();
  const double radius = report.at("yarns").at("median_radius").get<double>();
  // Heights are reported as shares of the base's diagonal.
  const double highest = report.at("height_max").get<double>() * diagonal;
  const double lowest = report.at("height_min").get<double>() * diagonal;
  std::printf("weave over the bunny: %d yarns, %.2f swatch lengths; heights %.3f to %.3f shells, yarn radius %.3f\n",
              report.at("yarns").at("yarns").get<int>(), report.at("yarns").at("in_swatch_lengths").get<double>(),
              lowest / shell, highest / shell, radius / shell);
  EXPECT_GE(report.at("yarns").at("in_swatch_lengths").get<double>(), 3.0);
  EXPECT_LE(highest, shell + radius);
  EXPECT_GE(lowest, -radius);
  EXPECT_GE(report.at("coverage").get<double>(), 0.95);

  // The ears, where cones crowd: cells a layout window folded round a cone left bare are seeded
  // again with a chart of their own, so the ears are covered as the body is.
  const TriMesh bunny = read_mesh(base);
  TriMesh ears;
  ears.positions = bunny.positions;
  for (const Tri& t : bunny.triangles)
    if (std::all_of(t.begin(), t.end(), [&](int32_t v) { return bunny.positions[v].y > kEarsAbove; }))
      ears.triangles.push_back(t);
  write_mesh(ears, dir / "ears.off");
  const auto on_ears = test::run_cli("inspect '" + (dir / "out.ply").string() + "' --swatch '" +
                                     (dir / "swatch.ply").string() + "' --base '" + (dir / "ears.off").string() +
                                     "' --json 2>/dev/null");
  ASSERT_EQ(on_ears.exit_code, 0) << on_ears.output;
  const double ear_coverage = nlohmann::json::parse(on_ears.output).at("coverage").get<double>();
  std::printf("coverage %.3f, of the ears %.3f\n", report.at("coverage").get<double>(), ear_coverage);
  EXPECT_GE(ear_coverage, kEarCoverage);
  std::filesystem::remove_all(dir);
}

// How the mail closes round the sphere's four half-turn cones (decision 0059): rings there link
// one fewer, none links five, and every ring of the whole linked to fewer than four lies within
// three ring radii of a cone (`inspect --near-cones`).
TEST(ConeClosure, TheSphereMailLinksFewerOnlyRoundItsCones) {
  const auto base = std::filesystem::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off";
  const auto dir = test::scratch_dir("element_size_cones");
  Job job;
  ASSERT_NO_FATAL_FAILURE(run_job(dir, "chainmail --rows 6 --columns 5 --ring-segments 16 --wire-segments 6", base,
                                  "--rings --near-cones '" + (dir / "stats.json").string() + "'", &job, "--seed 1"));
  const nlohmann::json& rings = job.report.at("rings");
  const nlohmann::json& near = rings.at("near");
  const auto whole = rings.at("links_histogram").get<std::vector<int>>();
  const auto round_cones = near.at("links_histogram").get<std::vector<int>>();
  const auto under_four = [](const std::vector<int>& histogram) {
    int n = 0;
    for (size_t k = 0; k < std::min<size_t>(4, histogram.size()); ++k) n += histogram[k];
    return n;
  };
  std::printf("sphere: %d rings near %d cones, %d of them linked to fewer than four, %d in the whole\n",
              near.at("rings").get<int>(), near.at("points").get<int>(), under_four(round_cones), under_four(whole));
  EXPECT_EQ(near.at("points").get<int>(), job.stats.at("cones").get<int>());
  EXPECT_LE(whole.size(), 5u);  // no ring links five or more
  EXPECT_GT(under_four(round_cones), 0);  // a cone costs links
  EXPECT_EQ(under_four(round_cones), under_four(whole));
  EXPECT_EQ(near.at("loose_rings").get<int>(), 0);
  EXPECT_GE(near.at("linked_to_3_share").get<double>(), 0.98);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Bases, ElementSize,
                         ::testing::Values("bunny.off", "spot_triangulated.obj", "decimated-max.obj"),
                         [](const auto& info) {
                           const std::string name(info.param);
                           std::string id = name.substr(0, name.find('.'));
                           for (char& c : id)
                             if (c == '-') c = '_';
                           return id;
                         });

}  // namespace
}  // namespace meshquilt
