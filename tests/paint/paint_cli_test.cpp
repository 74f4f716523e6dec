// `meshquilt paint` and `relief` end to end: a coloured and a raised sphere, relief from a bumped
// model, a base that passes through itself, and one-line errors.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "mesh/mesh_io.h"
#include "support/backends.h"
#include "support/run_cli.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

// 8 x 8: the left half red, the right half white.
void write_half_red_sample(const std::filesystem::path& file) {
  std::ofstream image(file, std::ios::binary);
  image << "P6\n8 8\n255\n";
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) image << (x < 4 ? std::string("\xff\x00\x00", 3) : std::string("\xff\xff\xff", 3));
}

TEST(PaintCli, ColoursTheSphereAndRefusesBadInput) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_paint_cli";
  std::filesystem::create_directories(dir);
  write_half_red_sample(dir / "sample.ppm");
  const std::string out = (dir / "out.ply").string();
  const test::CliResult r = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off --image " +
                              (dir / "sample.ppm").string() + " --scale 0.5 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const TriMesh painted = read_mesh(out);
  ASSERT_EQ(painted.colors.size(), painted.num_vertices());
  size_t red = 0;
  for (const auto& c : painted.colors) {
    EXPECT_EQ(c[0], 255);
    EXPECT_EQ(c[1], c[2]);
    red += c[1] == 0;
  }
  EXPECT_GT(red, painted.num_vertices() / 4);
  EXPECT_LT(red, 3 * painted.num_vertices() / 4);

  const test::CliResult missing = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) +
                                    "/data/sphere.off --image " + (dir / "none.png").string() + " -o " + out);
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("none.png"), std::string::npos) << missing.output;
  const test::CliResult window = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off --image " +
                                   (dir / "sample.ppm").string() + " --window 4 -o " + out);
  EXPECT_NE(window.exit_code, 0);
  EXPECT_NE(window.output.find("--window"), std::string::npos) << window.output;
  const test::CliResult tiny = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) +
                                             "/data/sphere.off --image " + (dir / "sample.ppm").string() +
                                             " --scale 1e-9 -o " + out);
  EXPECT_NE(tiny.exit_code, 0);
  EXPECT_NE(tiny.output.find("vertices (at most"), std::string::npos) << tiny.output;
  EXPECT_EQ(tiny.output.find("about -"), std::string::npos) << tiny.output;  // no overflow in the estimate
  // The good output is left as it was.
  EXPECT_EQ(read_mesh(out).colors.size(), painted.num_vertices());

  // --atlas: the base with a texture, as .glb only.
  const std::string glb = (dir / "atlas.glb").string();
  const test::CliResult baked = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off --image " +
                                              (dir / "sample.ppm").string() + " --scale 0.5 --atlas 64 -o " + glb);
  ASSERT_EQ(baked.exit_code, 0) << baked.output;
  std::ifstream glb_in(glb, std::ios::binary);
  const std::string glb_bytes((std::istreambuf_iterator<char>(glb_in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(glb_bytes.substr(0, 4), "glTF");
  EXPECT_NE(glb_bytes.find("TEXCOORD_0"), std::string::npos);
  EXPECT_NE(glb_bytes.find("\x89PNG"), std::string::npos);
  const test::CliResult not_glb = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off --image " +
                                                (dir / "sample.ppm").string() + " --atlas 64 -o " + out);
  EXPECT_EQ(not_glb.exit_code, window.exit_code);
  EXPECT_NE(not_glb.output.find("--atlas"), std::string::npos) << not_glb.output;
  EXPECT_EQ(read_mesh(out).colors.size(), painted.num_vertices());
}

TEST(PaintCli, ShrinksTheSampleToTheWidthAsked) {
  // 8 x 8, left half red, right half white: at 4 pixels across, two red columns and two white,
  // read at half the pixels per unit for the same --scale.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_paint_cli_width";
  std::filesystem::create_directories(dir);
  write_half_red_sample(dir / "sample.ppm");
  const std::string base = std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off", out = (dir / "out.ply").string();
  const auto stats_of = [&](const std::string& extra) {
    const std::string stats = (dir / "stats.json").string();
    const test::CliResult r = test::run_cli("paint --base " + base + " --image " + (dir / "sample.ppm").string() +
                                            " --scale 0.5 --backend cpu --progress none --stats " + stats + extra + " -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(stats);
    return nlohmann::json::parse(in);
  };
  const nlohmann::json whole = stats_of(""), half = stats_of(" --sample-width 4");
  EXPECT_EQ(half["sample"], nlohmann::json::array({4, 4}));
  EXPECT_NEAR(half["pixels_per_unit"].get<double>(), 0.5 * whole["pixels_per_unit"].get<double>(), 1e-9);
  // Red and white halves still: more red than white (green under half) at about half the vertices.
  const TriMesh painted = read_mesh(out);
  size_t red = 0;
  for (const auto& c : painted.colors) red += c[1] < 128;
  EXPECT_GT(red, painted.num_vertices() / 4);
  EXPECT_LT(red, 3 * painted.num_vertices() / 4);
  const std::string before = test::read_file(out);
  const test::CliResult grow = test::run_cli("paint --base " + base + " --image " + (dir / "sample.ppm").string() +
                                             " --sample-width 9 -o " + out);
  EXPECT_EQ(grow.exit_code, 6) << grow.output;
  EXPECT_NE(grow.output.find("--sample-width"), std::string::npos) << grow.output;
  EXPECT_EQ(test::read_file(out), before);
}

TEST(PaintCli, ReportsProgressAsJsonLines) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_paint_progress";
  std::filesystem::create_directories(dir);
  {
    std::ofstream image(dir / "sample.pgm", std::ios::binary);
    image << "P5\n8 8\n255\n";
    for (int k = 0; k < 64; ++k) image << static_cast<char>(37 * k);
  }
  const test::CliResult r = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off --image " +
                                          (dir / "sample.pgm").string() + " --scale 0.5 --backend cpu --progress json -o " +
                                          (dir / "out.ply").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line;
  nlohmann::json last_progress, done;
  int progress_lines = 0;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] != '{') continue;
    const nlohmann::json event = nlohmann::json::parse(line);
    ASSERT_EQ(event["task"], "paint");
    if (event["event"] == "progress") {
      ++progress_lines;
      last_progress = event;
    } else {
      done = event;
    }
  }
  EXPECT_GT(progress_lines, 2);
  EXPECT_LE(progress_lines, 202);
  EXPECT_EQ(last_progress["done"], last_progress["total"]);
  EXPECT_EQ(last_progress["done"], done["summary"]["visits"]);
  EXPECT_EQ(r.output.find("wrote "), std::string::npos) << r.output;
}

TEST(PaintCli, BothBackEndsWriteTheSameFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_paint_backends";
  std::filesystem::create_directories(dir);
  {
    std::ofstream image(dir / "sample.ppm", std::ios::binary);
    image << "P6\n12 12\n255\n";
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 12; ++x) image << static_cast<char>(20 * x) << static_cast<char>(19 * y) << static_cast<char>(13 * (x ^ y));
  }
  const auto run = [&](const std::string& backend) {
    const std::string out = (dir / (backend + ".ply")).string();
    const test::CliResult r = test::run_cli("paint --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off --image " +
                                            (dir / "sample.ppm").string() + " --scale 0.5 --backend " + backend + " -o " + out);
    std::ifstream in(out, std::ios::binary);
    return std::pair{r, std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())};
  };
  const auto [cpu, cpu_bytes] = run("cpu");
  ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
  const auto [vulkan, vulkan_bytes] = run("vulkan");
  if (vulkan.exit_code != 0) {
    if (test::ci()) FAIL() << "CI=true and no Vulkan device: " << vulkan.output;
    GTEST_SKIP() << "no Vulkan device: " << vulkan.output;
  }
  EXPECT_GT(cpu_bytes.size(), 1000u);
  EXPECT_TRUE(cpu_bytes == vulkan_bytes);
}

TEST(ReliefCli, RaisesTheSphereAndRefusesBadInput) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_relief_cli";
  std::filesystem::create_directories(dir);
  {
    // 8 x 8 grey: black and white columns.
    std::ofstream image(dir / "heights.pgm", std::ios::binary);
    image << "P5\n8 8\n255\n";
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) image << (x < 4 ? std::string("\x00", 1) : std::string("\xff", 1));
  }
  const std::string sphere = std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off";
  const std::string out = (dir / "out.ply").string();
  const test::CliResult r = test::run_cli("relief --base " + sphere + " --image " + (dir / "heights.pgm").string() +
                                          " --height 0.05 --scale 0.5 -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const TriMesh raised = read_mesh(out);
  // The sphere of radius 0.5 refined: its vertices lie within the facets' sag below 0.5, and
  // raised ones up to 0.05 above.
  size_t up = 0;
  for (const Vec3& p : raised.positions) {
    const double radius = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    EXPECT_LT(radius, 0.5 + 0.05 + 1e-4);  // normals of the facets, not quite radial
    up += radius > 0.52;
  }
  EXPECT_GT(up, raised.num_vertices() / 4);
  EXPECT_LT(up, 3 * raised.num_vertices() / 4);
  const test::CliResult no_height =
      test::run_cli("relief --base " + sphere + " --image " + (dir / "heights.pgm").string() + " --height 0 -o " + out);
  EXPECT_NE(no_height.exit_code, 0);
  EXPECT_NE(no_height.output.find("--height"), std::string::npos) << no_height.output;
}

TEST(ReliefCli, SaysWhereTheBasePassesThroughItself) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_relief_crossing_cli";
  std::filesystem::create_directories(dir);
  write_half_red_sample(dir / "heights.ppm");
  // data/sphere.off (radius 0.5) and its copy 0.6 along x, as one mesh: they cross on a circle.
  const TriMesh one = read_mesh(std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off");
  TriMesh both = one;
  const int32_t offset = static_cast<int32_t>(one.num_vertices());
  for (const Vec3& p : one.positions) both.positions.push_back(p + Vec3(0.6, 0.0, 0.0));
  for (const Tri& t : one.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  write_mesh(both, (dir / "two.off").string());
  const std::string common = " --image " + (dir / "heights.ppm").string() + " --height 0.02 --scale 0.5 --stats " +
                             (dir / "stats.json").string() + " -o " + (dir / "out.ply").string();
  const test::CliResult crossed = test::run_cli("relief --base " + (dir / "two.off").string() + common);
  ASSERT_EQ(crossed.exit_code, 0) << crossed.output;
  EXPECT_NE(crossed.output.find("two.off passes through itself"), std::string::npos) << crossed.output;
  EXPECT_GT(nlohmann::json::parse(std::ifstream(dir / "stats.json"))["crossing_face_pairs_left"].get<int>(), 0);
  const test::CliResult single =
      test::run_cli("relief --base " + std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off" + common);
  ASSERT_EQ(single.exit_code, 0) << single.output;
  EXPECT_EQ(single.output.find("passes through itself"), std::string::npos) << single.output;
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(dir / "stats.json"))["crossing_face_pairs_left"].get<int>(), 0);
}

TEST(ReliefCli, TakesItsSampleFromAModelsDetail) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mq_relief_from_cli";
  std::filesystem::create_directories(dir);
  // A sphere of radius 0.5 bumped by +-0.02.
  TriMesh model = test::icosphere(4, 0.5);
  for (Vec3& p : model.positions) {
    const Vec3 u = p / std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    p = u * (0.5 + 0.02 * std::sin(20.0 * u.x) * std::sin(20.0 * u.y) * std::sin(20.0 * u.z));
  }
  write_mesh(model, (dir / "bumped.ply").string());
  const std::string sphere = std::string(MESHQUILT_SOURCE_DIR) + "/data/sphere.off";
  const std::string out = (dir / "out.ply").string(), stats = (dir / "stats.json").string();
  const test::CliResult r = test::run_cli("relief --base " + sphere + " --from " + (dir / "bumped.ply").string() +
                                          " --smoothing 0.1 --scale 0.5 --stats " + stats + " -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(stats);
  const nlohmann::json s = nlohmann::json::parse(in);
  // The region's heights span the bumps' 0.04, give or take their attenuation and the sampling.
  const double span = s["from"]["detail_high"].get<double>() - s["from"]["detail_low"].get<double>();
  EXPECT_GT(span, 0.025);
  EXPECT_LT(span, 0.06);
  EXPECT_GT(s["height"].get<double>(), 0.0);
  const TriMesh raised = read_mesh(out);
  size_t up = 0;
  for (const Vec3& p : raised.positions) up += std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) > 0.5 + 0.2 * s["height"].get<double>();
  EXPECT_GT(up, raised.num_vertices() / 10);

  const test::CliResult both = test::run_cli("relief --base " + sphere + " --from " + (dir / "bumped.ply").string() +
                                             " --image x.png -o " + out);
  EXPECT_NE(both.exit_code, 0);
  EXPECT_NE(both.output.find("--from"), std::string::npos) << both.output;
  const test::CliResult missing =
      test::run_cli("relief --base " + sphere + " --from " + (dir / "none.ply").string() + " -o " + out);
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("none.ply"), std::string::npos) << missing.output;
  const test::CliResult region = test::run_cli("relief --base " + sphere + " --from " + (dir / "bumped.ply").string() +
                                               " --region 0,0,0.5,-1 -o " + out);
  EXPECT_NE(region.exit_code, 0);
  EXPECT_NE(region.output.find("--region"), std::string::npos) << region.output;
  // A flat model has no detail: its file is named.
  const std::string flat_model = (dir / "flat.off").string();
  write_mesh(test::flat_grid(32, 32, 1.0 / 32), flat_model);
  const test::CliResult smooth =
      test::run_cli("relief --base " + sphere + " --from " + flat_model + " --region 0.5,0.5,0,0.4 -o " + out);
  EXPECT_NE(smooth.exit_code, 0);
  EXPECT_NE(smooth.output.find("flat.off: --from: no detail"), std::string::npos) << smooth.output;
  // The good output is left as it was.
  EXPECT_EQ(read_mesh(out).num_vertices(), raised.num_vertices());
}

}  // namespace
}  // namespace meshquilt
