// The `meshquilt inspect` command end to end: JSON output parsed back, and one-line errors with
// the file name and a non-zero exit code for bad files.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "mesh/mesh_io.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

TriMesh torus(const Vec3& center, const Vec3& a, const Vec3& b, double R, double r, int nu, int nv) {
  TriMesh m;
  const Vec3 n = glm::cross(a, b);
  for (int i = 0; i < nu; ++i) {
    const double u = 2.0 * std::numbers::pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2.0 * std::numbers::pi * j / nv;
      m.positions.push_back(center + (R + r * std::cos(v)) * (std::cos(u) * a + std::sin(u) * b) + r * std::sin(v) * n);
    }
  }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

std::string quote(const std::string& s) {
  std::string q("'");
  q.append(s).append("'");
  return q;
}

struct CliRun {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class InspectCli : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::exists(MESHQUILT_CLI)) << "build the meshquilt executable first: " << MESHQUILT_CLI;
    dir_ = fs::temp_directory_path() / ("meshquilt_inspect_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `meshquilt inspect ARGS...`, each argument quoted for the shell.
  CliRun run(const std::vector<std::string>& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    std::string command = quote(MESHQUILT_CLI);
    command.append(" inspect");
    for (const std::string& a : args) command.append(" ").append(quote(a));
    command.append(" >").append(quote(out.string())).append(" 2>").append(quote(err.string()));
    const int status = std::system(command.c_str());
    CliRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  fs::path dir_;
};

TEST_F(InspectCli, JsonReportOfLinkedRings) {
  TriMesh m = torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.25, 32, 12);
  const TriMesh b = torus({1, 0, 0}, {1, 0, 0}, {0, 0, 1}, 1.0, 0.25, 32, 12);
  const auto n = static_cast<int32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (const Tri& t : b.triangles) m.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  const fs::path file = dir_ / "rings.ply";
  write_mesh(m, file);

  const CliRun r = run({file.string(), "--json", "--swatch", file.string(), "--plane"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("faces").get<int64_t>(), 2 * 32 * 12 * 2);
  EXPECT_EQ(j.at("vertices").get<int64_t>(), 2 * 32 * 12);
  EXPECT_EQ(j.at("elements").get<int>(), 2);
  EXPECT_EQ(j.at("closed_elements").get<int>(), 2);
  EXPECT_EQ(j.at("boundary_edges").get<int>(), 0);
  EXPECT_EQ(j.at("nonmanifold_edges").get<int>(), 0);
  EXPECT_EQ(j.at("nonmanifold_vertices").get<int>(), 0);
  EXPECT_EQ(j.at("intersecting_face_pairs").get<int>(), 0);
  EXPECT_EQ(j.at("self_intersecting_face_pairs").get<int>(), 0);
  EXPECT_EQ(j.at("swatch_elements").get<int>(), 2);
  EXPECT_DOUBLE_EQ(j.at("element_area_ks").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j.at("element_extent_ks").get<double>(), 0.0);
  EXPECT_GT(j.at("coverage").get<double>(), 0.0);
  EXPECT_LE(j.at("coverage").get<double>(), 1.0);
}

// The link graph of a quilted chain mail: a planar quilt of the generator's mail is one linked
// piece in which rings away from the border pass through four others, at the swatch's ring size.
TEST_F(InspectCli, RingsOfAQuiltedChainMail) {
  const fs::path swatch = dir_ / "chain.ply", quilt = dir_ / "quilt.ply", stats = dir_ / "stats.json";
  const std::string cli = quote(MESHQUILT_CLI);
  ASSERT_EQ(std::system((cli + " swatch chainmail --rows 6 --columns 5 -o " + quote(swatch.string()) + " >/dev/null").c_str()), 0);
  ASSERT_EQ(std::system((cli + " synth --swatch " + quote(swatch.string()) + " --plane 2x2 --backend cpu --progress none" +
                         " --stats " + quote(stats.string()) + " -o " + quote(quilt.string()) + " >/dev/null")
                            .c_str()),
            0);
  const nlohmann::json rect = nlohmann::json::parse(slurp(stats)).at("plane_rect");
  const std::string region = std::to_string(rect[0].get<double>()) + "," + std::to_string(rect[1].get<double>()) + "," +
                             std::to_string(rect[2].get<double>()) + "," + std::to_string(rect[3].get<double>());
  const CliRun r = run({quilt.string(), "--rings", "--swatch", swatch.string(), "--plane", "--region", region, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json k = nlohmann::json::parse(r.out).at("rings");
  const int rings = k.at("rings").get<int>();
  EXPECT_EQ(rings, nlohmann::json::parse(r.out).at("elements").get<int>());
  EXPECT_EQ(k.at("pieces").get<int>(), 1);
  EXPECT_EQ(k.at("loose_rings").get<int>(), 0);
  EXPECT_GT(k.at("linked_to_3_share").get<double>(), 0.7);
  EXPECT_EQ(k.at("links_histogram").size(), 5u);  // nobody links more than four
  EXPECT_NEAR(k.at("radius_ratio").get<double>(), 1.0, 0.05);
  // The plane holds the swatch's density of rings, less a border's worth at most.
  EXPECT_NEAR(k.at("missing_rings").get<double>(), 0.0, 0.1 * k.at("expected_rings").get<double>());
}

// Rings of a swatch grown to known sizes over a base: radius over asked follows from the scale
// alone (the swatch's longer side over the base's diagonal), whatever the base's units.
TEST_F(InspectCli, RingRadiusOverTheSizeAsked) {
  const fs::path swatch_file = dir_ / "swatch.ply", layer_file = dir_ / "layer.ply", base_file = dir_ / "base.ply";
  TriMesh swatch;
  for (int k = 0; k < 4; ++k) {
    const TriMesh ring = torus({3.0 * k, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.2, 32, 8);
    const auto n = static_cast<int32_t>(swatch.positions.size());
    swatch.positions.insert(swatch.positions.end(), ring.positions.begin(), ring.positions.end());
    for (const Tri& t : ring.triangles) swatch.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  }
  write_mesh(swatch, swatch_file);
  const double longer = 3.0 * 3 + 2.4;  // x extent: four rings of outer radius 1.2, three apart
  // A base box with diagonal 300 and, over it, ten rings of radius 10 x (0.8, 0.85, ..., 1.25).
  TriMesh base = torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 100.0, 20.0, 32, 8);
  write_mesh(base, base_file);
  const Vec3 extent(240.0, 240.0, 40.0);
  const double scale = longer * 10.0 / glm::length(extent);  // asks for rings of radius 10
  TriMesh layer;
  for (int k = 0; k < 10; ++k) {
    const double size = 0.8 + 0.05 * k;
    const TriMesh ring = torus({40.0 * k - 200.0, 0, 30}, {1, 0, 0}, {0, 1, 0}, 10.0 * size, 1.0, 32, 8);
    const auto n = static_cast<int32_t>(layer.positions.size());
    layer.positions.insert(layer.positions.end(), ring.positions.begin(), ring.positions.end());
    for (const Tri& t : ring.triangles) layer.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  }
  write_mesh(layer, layer_file);
  const CliRun r = run({layer_file.string(), "--rings", "--swatch", swatch_file.string(), "--base",
                        base_file.string(), "--scale", std::to_string(scale), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json k = nlohmann::json::parse(r.out).at("rings");
  EXPECT_NEAR(k.at("asked_radius").get<double>(), 10.0, 0.05);
  const nlohmann::json over = k.at("radius_over_asked");
  EXPECT_NEAR(over.at("p10").get<double>(), 0.85, 0.01);
  EXPECT_NEAR(over.at("median").get<double>(), 1.025, 0.03);
  EXPECT_NEAR(over.at("p90").get<double>(), 1.2, 0.01);
  EXPECT_NEAR(k.at("median_aspect").get<double>(), 1.0, 0.01);
  // Without a base the scale has nothing to measure against.
  EXPECT_NE(run({layer_file.string(), "--rings", "--scale", "0.1"}).code, 0);
}

TEST_F(InspectCli, BaseHeightsAndReadableReport) {
  TriMesh base;
  base.positions = {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}};
  base.triangles = {{0, 1, 2}, {0, 2, 3}};
  const fs::path base_file = dir_ / "base.obj", ring_file = dir_ / "ring.off";
  write_mesh(base, base_file);
  write_mesh(torus({0, 0, 0.5}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.25, 32, 12), ring_file);
  const CliRun r = run({ring_file.string(), "--base", base_file.string(), "--shell-height", "0.1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const double diagonal = std::sqrt(32.0);
  EXPECT_NEAR(j.at("height_min").get<double>(), 0.25 / diagonal, 1e-9);
  EXPECT_NEAR(j.at("height_max").get<double>(), 0.75 / diagonal, 1e-9);
  // H = 0.1 diagonals = 0.566: the vertices above it are outside.
  int expected = 0;
  for (const Vec3& p : torus({0, 0, 0.5}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.25, 32, 12).positions) expected += p.z > 0.1 * diagonal;
  EXPECT_EQ(j.at("outside_shell_vertices").get<int>(), expected);

  const CliRun text = run({ring_file.string()});
  ASSERT_EQ(text.code, 0);
  EXPECT_NE(text.out.find("elements:"), std::string::npos);
  EXPECT_NE(text.out.find("1, of which 1 closed"), std::string::npos);
}

// A base wound inward, as some files come, is read as synth reads it (each part turned outward):
// heights of a ring above a dome come out the same from either winding.
TEST_F(InspectCli, BaseHeightsDoNotDependOnTheBasesWinding) {
  TriMesh dome;  // the upper half of a unit sphere, open at its rim, wound outward
  const int rings = 8, around = 24;
  dome.positions.push_back({0, 0, 1});
  for (int i = 1; i <= rings; ++i)
    for (int k = 0; k < around; ++k) {
      const double polar = 0.5 * std::numbers::pi * i / rings, azimuth = 2.0 * std::numbers::pi * k / around;
      dome.positions.push_back({std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)});
    }
  const auto at = [&](int i, int k) { return i == 0 ? 0 : 1 + (i - 1) * around + (k % around); };
  for (int k = 0; k < around; ++k) dome.triangles.push_back({at(0, 0), at(1, k), at(1, k + 1)});
  for (int i = 1; i < rings; ++i)
    for (int k = 0; k < around; ++k) {
      dome.triangles.push_back({at(i, k), at(i + 1, k), at(i + 1, k + 1)});
      dome.triangles.push_back({at(i, k), at(i + 1, k + 1), at(i, k + 1)});
    }
  TriMesh inward = dome;
  for (Tri& t : inward.triangles) std::swap(t[1], t[2]);
  const fs::path out_file = dir_ / "out.obj", in_file = dir_ / "in.obj", ring_file = dir_ / "ring.off";
  write_mesh(dome, out_file);
  write_mesh(inward, in_file);
  write_mesh(torus({0, 0, 1.2}, {1, 0, 0}, {0, 1, 0}, 0.1, 0.02, 24, 8), ring_file);
  const CliRun outward_run = run({ring_file.string(), "--base", out_file.string(), "--json"});
  const CliRun inward_run = run({ring_file.string(), "--base", in_file.string(), "--json"});
  ASSERT_EQ(outward_run.code, 0) << outward_run.err;
  ASSERT_EQ(inward_run.code, 0) << inward_run.err;
  const nlohmann::json a = nlohmann::json::parse(outward_run.out), b = nlohmann::json::parse(inward_run.out);
  EXPECT_GT(a.at("height_min").get<double>(), 0.0);  // above the dome, outside it
  EXPECT_NEAR(b.at("height_min").get<double>(), a.at("height_min").get<double>(), 1e-9);
  EXPECT_NEAR(b.at("height_max").get<double>(), a.at("height_max").get<double>(), 1e-9);
}

bool one_line_naming(const std::string& err, const std::string& name) {
  return !err.empty() && err.find('\n') == err.size() - 1 && err.find(name) != std::string::npos;
}

// --region measures the rectangle given (synth's plane_rect) instead of the footprint: a ring
// covering x-y [-1.25, 1.25]^2 on cells of 1.25 (half its extent) over a rectangle 10 x 2.5
// whose cell edges lie at -0.625 and 0.625 touches 3 of its 8 columns.
TEST_F(InspectCli, RegionReplacesTheFootprint) {
  const fs::path ring_file = dir_ / "ring.ply";
  write_mesh(torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.25, 64, 12), ring_file);
  const CliRun wide = run({ring_file.string(), "--plane", "--region", "-1.875,-1.25,8.125,1.25", "--json"});
  ASSERT_EQ(wide.code, 0) << wide.err;
  EXPECT_NEAR(nlohmann::json::parse(wide.out).at("coverage").get<double>(), 3.0 / 8.0, 1e-12);
  EXPECT_EQ(run({ring_file.string(), "--region", "0,0,1,1"}).code, 2);  // needs --plane
  const CliRun empty = run({ring_file.string(), "--plane", "--region", "0,0,0,1"});
  EXPECT_EQ(empty.code, 6);  // ErrorKind::invalid_option
  EXPECT_TRUE(one_line_naming(empty.err, "region")) << empty.err;
}

// Rings near points a synth --stats file lists as cones: a linked pair and a loose ring.
TEST_F(InspectCli, RingsNearTheConesOfAStatsFile) {
  TriMesh m = torus({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.25, 32, 12);
  for (const TriMesh& b : {torus({1, 0, 0}, {1, 0, 0}, {0, 0, 1}, 1.0, 0.25, 32, 12),
                           torus({10, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.25, 32, 12)}) {
    const auto n = static_cast<int32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (const Tri& t : b.triangles) m.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  }
  const fs::path file = dir_ / "rings.ply", stats = dir_ / "stats.json";
  write_mesh(m, file);
  std::ofstream(stats) << R"({"cones": 2, "cone_points": [[0.5, 0, 0], [10, 0, 0.5]]})";

  const CliRun r = run({file.string(), "--json", "--rings", "--near-cones", stats.string(), "--near-radius", "1.5"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json near = nlohmann::json::parse(r.out).at("rings").at("near");
  EXPECT_EQ(near.at("points").get<int>(), 2);
  EXPECT_EQ(near.at("rings").get<int>(), 3);
  EXPECT_EQ(near.at("loose_rings").get<int>(), 1);
  EXPECT_EQ(near.at("links_histogram").get<std::vector<int>>(), (std::vector<int>{1, 2}));
  // 1.5 median ring radii: the loose ring's centre is 0.5 from its point, the pair's 0.5 from theirs.
  EXPECT_NEAR(near.at("radius").get<double>(), 1.5, 0.05);
  const CliRun tight = run({file.string(), "--json", "--rings", "--near-cones", stats.string(), "--near-radius", "0.4"});
  ASSERT_EQ(tight.code, 0) << tight.err;
  EXPECT_EQ(nlohmann::json::parse(tight.out).at("rings").at("near").at("rings").get<int>(), 0);

  const fs::path other = dir_ / "other.json";
  std::ofstream(other) << R"({"elements": 3})";
  const CliRun wrong = run({file.string(), "--rings", "--near-cones", other.string()});
  EXPECT_EQ(wrong.code, 6);  // ErrorKind::invalid_option
  EXPECT_TRUE(one_line_naming(wrong.err, "other.json")) << wrong.err;
  const CliRun missing = run({file.string(), "--rings", "--near-cones", (dir_ / "none.json").string()});
  EXPECT_EQ(missing.code, 3);  // ErrorKind::file_unreadable
  EXPECT_TRUE(one_line_naming(missing.err, "none.json")) << missing.err;
  EXPECT_EQ(run({file.string(), "--near-cones", stats.string()}).code, 2);  // needs --rings
}

TEST_F(InspectCli, BrokenAndMissingFilesGiveOneLineErrors) {
  const fs::path broken = dir_ / "broken.off";
  std::ofstream(broken) << "OFF\n4 2 0\n0 0 0\n1 0 0\n";  // truncated
  const CliRun r = run({broken.string(), "--json"});
  EXPECT_NE(r.code, 0);
  EXPECT_TRUE(one_line_naming(r.err, "broken.off")) << r.err;
  EXPECT_TRUE(r.out.empty());

  // Faces that all collapse when coincident vertices are welded.
  const fs::path flat = dir_ / "collapsed.obj";
  std::ofstream(flat) << "v 0 0 0\nv 0 0 0\nv 1 1 1\nf 1 2 3\n";
  const CliRun collapsed = run({flat.string()});
  EXPECT_EQ(collapsed.code, 5);  // ErrorKind::invalid_mesh
  EXPECT_TRUE(one_line_naming(collapsed.err, "collapsed.obj")) << collapsed.err;

  const CliRun missing = run({(dir_ / "nowhere.ply").string()});
  EXPECT_EQ(missing.code, 3);  // ErrorKind::file_unreadable
  EXPECT_TRUE(one_line_naming(missing.err, "nowhere.ply")) << missing.err;

  const CliRun both = run({broken.string(), "--plane", "--base", broken.string()});
  EXPECT_EQ(both.code, 2);  // --plane and --base exclude each other: usage error
}

}  // namespace
}  // namespace meshquilt
