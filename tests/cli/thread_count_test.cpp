// The same bytes for any thread count: synthesis on one CPU and on every CPU this machine gives
// it, over a plane (lattice copies), a twill (yarns stitched at every seam) and the sphere.
#include <gtest/gtest.h>

#include <string>

#include "support/golden.h"
#include "support/run_cli.h"

namespace meshquilt {
namespace {

struct Job {
  const char* name;
  const char* swatch_args;  // empty: the built-in swatch
  const char* synth_args;
};

class ThreadCount : public ::testing::TestWithParam<Job> {};

// Runs synth with `prefix` before the executable (e.g. a taskset); returns the output's bytes.
std::string synth(const std::string& prefix, const std::string& args, const std::filesystem::path& out,
                  std::string* log) {
  const std::string command =
      prefix + " '" + MESHQUILT_CLI + "' synth " + args + " --backend cpu -o '" + out.string() + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return {};
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) log->append(buffer, n);
  EXPECT_EQ(pclose(pipe), 0) << *log;
  return test::read_file(out);
}

TEST_P(ThreadCount, OneThreadGivesTheBytesOfAll) {
  const Job& job = GetParam();
  const auto dir = test::scratch_dir(std::string("threads_") + job.name);
  std::string args = std::string(job.synth_args) + " --progress none";
  if (*job.swatch_args) {
    const auto swatch = dir / "swatch.ply";
    const auto made = test::run_cli(std::string("swatch ") + job.swatch_args + " -o '" + swatch.string() + "'");
    ASSERT_EQ(made.exit_code, 0) << made.output;
    args += " --swatch '" + swatch.string() + "'";
  }
  std::string one_log, all_log;
  const std::string one = synth("taskset -c 0", args, dir / "one.ply", &one_log);
  const std::string all = synth("", args, dir / "all.ply", &all_log);
  EXPECT_NE(one_log.find("(1 thread"), std::string::npos) << one_log;
  ASSERT_FALSE(one.empty());
  EXPECT_TRUE(one == all) << job.name << ": one thread and all threads wrote different bytes\n" << all_log;
}

INSTANTIATE_TEST_SUITE_P(
    Jobs, ThreadCount,
    ::testing::Values(Job{"mail_plane", "chainmail --preset small --seed 3", "--plane 3x3"},
                      Job{"twill_plane", "weave --pattern twill:2/2 --preset small", "--plane 2x2"},
                      Job{"fruit_plane", "fruit --preset small", "--plane 2x2"},
                      Job{"sphere", "", "--base '" MESHQUILT_SOURCE_DIR "/data/sphere.off' --scale 0.3"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace meshquilt
