// Golden outputs of planar quilting: the built-in job, a twill weave and a chain mail on small
// presets must stay byte-identical across refactorings of the scheduler. A change that alters
// them on purpose updates the hashes in the same commit and says why (with inspect figures).
#include <gtest/gtest.h>

#include <string>

#include "support/golden.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

struct Golden {
  const char* name;
  const char* swatch_args;  // empty: the built-in swatch
  const char* synth_args;
  const char* hash;
};

class PlanarGolden : public ::testing::TestWithParam<Golden> {};

TEST_P(PlanarGolden, OutputIsByteIdentical) {
  const Golden& g = GetParam();
  const auto dir = test::scratch_dir(std::string("golden_") + g.name);
  std::string swatch_option;
  if (*g.swatch_args) {
    const auto swatch = dir / "swatch.ply";
    const auto made = test::run_cli(std::string("swatch ") + g.swatch_args + " -o '" + swatch.string() + "'");
    ASSERT_EQ(made.exit_code, 0) << made.output;
    swatch_option = "--swatch '" + swatch.string() + "' ";
  }
  const auto out = dir / "out.ply";
  const auto run = test::run_cli("synth " + swatch_option + g.synth_args + " --backend cpu --progress none -o '" +
                                 out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(test::fnv1a_hex(test::read_file(out)), g.hash) << g.name;
}

INSTANTIATE_TEST_SUITE_P(
    Presets, PlanarGolden,
    ::testing::Values(Golden{"builtin", "", "--plane 2x2 --seed 3", "bd0bccf84bcb1419"},
                      Golden{"twill", "weave --pattern twill:2/3 --preset small", "--plane 4x4 --seed 11", "748bdb6cd8601216"},
                      Golden{"chainmail", "chainmail --preset small", "--plane 4x4 --seed 5", "ff28ae0c153e44bd"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace meshquilt
