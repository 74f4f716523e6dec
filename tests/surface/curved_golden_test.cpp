// Golden outputs of quilting over curved bases (Section 3 of the mesh quilting paper): the bunny
// through the stretch-minimized shell map with its texture-space file and re-embeddings, the open
// teapot by normal displacement, and the two-component knot. Outputs must stay byte-identical
// across refactorings; a change that alters them on purpose updates the hashes in the same commit
// and says why (with inspect figures).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/golden.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

std::filesystem::path shared_mesh(const std::string& name) {
  return std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes" / name;
}

// The small chain mail preset, written into `dir`.
std::string small_chain_mail(const std::filesystem::path& dir) {
  const auto swatch = dir / "chain.ply";
  const auto made = test::run_cli("swatch chainmail --preset small -o '" + swatch.string() + "'");
  EXPECT_EQ(made.exit_code, 0) << made.output;
  return swatch.string();
}

struct CurvedGolden {
  const char* name;
  const char* base;
  const char* synth_args;
  const char* hash;
};

class CurvedGoldenTest : public ::testing::TestWithParam<CurvedGolden> {};

TEST_P(CurvedGoldenTest, OutputIsByteIdentical) {
  const CurvedGolden& g = GetParam();
  if (!std::filesystem::exists(shared_mesh(g.base))) GTEST_SKIP() << "../shared not found";
  const auto dir = test::scratch_dir(std::string("curved_golden_") + g.name);
  const auto out = dir / "out.ply";
  const auto run = test::run_cli("synth --swatch '" + small_chain_mail(dir) + "' --base '" + shared_mesh(g.base).string() +
                                 "' " + g.synth_args + " --backend cpu --progress none -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(test::fnv1a_hex(test::read_file(out)), g.hash) << g.name;
}

INSTANTIATE_TEST_SUITE_P(
    Bases, CurvedGoldenTest,
    ::testing::Values(CurvedGolden{"bunny_shell", "bunny.off", "--scale 0.15 --seed 2", "0e1134e142ff3867"},
                      CurvedGolden{"teapot_normal", "teapot.obj", "--scale 0.15 --embed normal --seed 3",
                                   "c9206c2dd839eb9d"},
                      CurvedGolden{"two_knots", "knot2.off", "--scale 0.2 --seed 4", "25571967680ceb22"}),
    [](const auto& info) { return std::string(info.param.name); });

// The texture-space file of the bunny job, and `embed` from it: over the same base as synth
// embedded it (the shell map), which must give synth's own output back, and by displacement.
TEST(CurvedGolden, TextureFileAndEmbedOutputsAreByteIdentical) {
  const auto bunny = shared_mesh("bunny.off");
  if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "../shared not found";
  const auto dir = test::scratch_dir("curved_golden_texture");
  const auto out = dir / "out.ply", texture = dir / "bunny.mqt";
  const auto run = test::run_cli("synth --swatch '" + small_chain_mail(dir) + "' --base '" + bunny.string() +
                                 "' --scale 0.15 --seed 2 --backend cpu --progress none --write-texture '" +
                                 texture.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(test::fnv1a_hex(test::read_file(texture)), "91b75fbfa0b86cef");

  const auto shell = dir / "shell.ply", normal = dir / "normal.ply";
  const auto embed = [&](const std::string& args, const std::filesystem::path& to) {
    return test::run_cli("embed --texture '" + texture.string() + "' --base '" + bunny.string() + "' " + args + " -o '" +
                         to.string() + "'");
  };
  const auto shell_run = embed("", shell);
  ASSERT_EQ(shell_run.exit_code, 0) << shell_run.output;
  EXPECT_EQ(test::read_file(shell), test::read_file(out));
  const auto normal_run = embed("--embed normal", normal);
  ASSERT_EQ(normal_run.exit_code, 0) << normal_run.output;
  EXPECT_EQ(test::fnv1a_hex(test::read_file(normal)), "f04ce1283855db55");
}

// On the weave's periods, copies of a yarn placed end to end are joined into one element; the
// texture holds the joined yarns, and `embed` must place each as synth did.
TEST(CurvedGolden, JoinedYarnsEmbedBackAsSynthPlacedThem) {
  const auto dir = test::scratch_dir("curved_golden_joined");
  const auto weave = dir / "weave.ply", out = dir / "out.ply", texture = dir / "sphere.mqt", stats = dir / "stats.json";
  ASSERT_EQ(test::run_cli("swatch weave --preset small -o '" + weave.string() + "'").exit_code, 0);
  const auto sphere = std::filesystem::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off";
  const auto run = test::run_cli("synth --swatch '" + weave.string() + "' --base '" + sphere.string() +
                                 "' --scale 0.3 --backend cpu --progress none --stats '" + stats.string() +
                                 "' --write-texture '" + texture.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string figures = test::read_file(stats);
  const size_t at = figures.find("\"joined_elements\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GT(std::stoi(figures.substr(at + std::string("\"joined_elements\": ").size())), 0);
  const auto embedded = dir / "embedded.ply";
  const auto embed_run = test::run_cli("embed --texture '" + texture.string() + "' --base '" + sphere.string() + "' -o '" +
                                       embedded.string() + "'");
  ASSERT_EQ(embed_run.exit_code, 0) << embed_run.output;
  EXPECT_EQ(test::read_file(embedded), test::read_file(out));
}

}  // namespace
}  // namespace meshquilt
