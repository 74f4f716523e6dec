// Hardened inputs and outputs through the CLI: memory estimates and budgets, absurd swatches,
// peak memory of refused inputs, SIGKILL at random moments during a large write, SIGINT/SIGTERM.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <random>
#include <thread>

#include "support/run_cli.h"
#include "support/spawn.h"

namespace meshquilt::test {
namespace {

using Clock = std::chrono::steady_clock;

size_t count_lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

std::vector<std::string> temporaries(const std::filesystem::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 4 && name.substr(name.size() - 4) == ".tmp") found.push_back(name);
  }
  return found;
}

// Waits for `pid` at most `seconds`; kills it (and fails) when it runs on.
ChildEnd wait_at_most(pid_t pid, double seconds) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < deadline) {
    siginfo_t info{};
    if (waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid) return wait_child(pid);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  ADD_FAILURE() << "still running after " << seconds << " s";
  return wait_child(pid);
}

TEST(SynthLimits, HugePlaneIsRefusedUpFront) {
  const auto dir = scratch_dir("synth_huge_plane");
  write_file(dir / "out.ply", "previous");
  const auto start = Clock::now();
  const CliResult r = run_cli("synth --progress none --plane 1000x1000 -o '" + (dir / "out.ply").string() + "'");
  EXPECT_EQ(r.exit_code, 11) << r.output;
  EXPECT_NE(r.output.find("--plane 1000x1000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("raise it with --max-memory"), std::string::npos) << r.output;
  EXPECT_EQ(count_lines(r.output), 1u) << r.output;
  EXPECT_EQ(read_file(dir / "out.ply"), "previous");
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 60.0);  // refused, not run
}

TEST(SynthLimits, MaxMemoryLowersAndRaisesTheBudget) {
  const auto dir = scratch_dir("synth_max_memory");
  const CliResult low = run_cli("synth --progress none --plane 1x1 --max-memory 1M -o '" + (dir / "o.ply").string() + "'");
  EXPECT_EQ(low.exit_code, 11) << low.output;
  EXPECT_NE(low.output.find("memory budget 1.0 MiB"), std::string::npos) << low.output;
  const CliResult bad = run_cli("synth --progress none --max-memory lots -o '" + (dir / "o.ply").string() + "'");
  EXPECT_EQ(bad.exit_code, 6) << bad.output;
  EXPECT_NE(bad.output.find("--max-memory"), std::string::npos) << bad.output;
  EXPECT_EQ(count_lines(bad.output), 1u) << bad.output;
}

// A binary STL weave swatch with one coordinate moved to about 3e38 (the mutated file).
TEST(SynthLimits, StrayVertexNear3e38EndsWithOneLine) {
  const auto dir = scratch_dir("synth_stray_vertex");
  ASSERT_EQ(run_cli("swatch weave --preset small -o '" + (dir / "weave.stl").string() + "'").exit_code, 0);
  std::string stl = read_file(dir / "weave.stl");
  ASSERT_GT(stl.size(), 200u);
  const float far = 3e38f;
  std::memcpy(stl.data() + 84 + 12, &far, 4);  // first vertex of the first triangle, x
  write_file(dir / "stray.stl", stl);
  write_file(dir / "out.ply", "previous");
  const pid_t pid = spawn_cli({"synth", "--progress", "none", "--swatch", (dir / "stray.stl").string(), "--plane", "1x1",
                               "--max-patches", "2", "-o", (dir / "out.ply").string()},
                              (dir / "log.txt").string());
  const ChildEnd end = wait_at_most(pid, 120.0);
  const std::string log = read_file(dir / "log.txt");
  EXPECT_EQ(end.exit_code, 5) << log;
  EXPECT_NE(log.find("stray.stl: degenerate swatch"), std::string::npos) << log;
  EXPECT_EQ(count_lines(log), 1u) << log;
  EXPECT_EQ(read_file(dir / "out.ply"), "previous");
}

// A vertex moved far away but within the coordinate range: named as the stray one.
TEST(SynthLimits, StrayVertexWithinRangeIsNamed) {
  const auto dir = scratch_dir("synth_stray_named");
  ASSERT_EQ(run_cli("swatch weave --preset small -o '" + (dir / "weave.stl").string() + "'").exit_code, 0);
  std::string stl = read_file(dir / "weave.stl");
  const float far[3] = {1e9f, 1e9f, 1e9f};
  std::memcpy(stl.data() + 84 + 12, far, 12);
  write_file(dir / "stray.stl", stl);
  const CliResult r = run_cli("synth --progress none --swatch '" + (dir / "stray.stl").string() + "' --plane 1x1 -o '" +
                              (dir / "o.ply").string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.output;
  EXPECT_NE(r.output.find("median edge lengths"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("at (1e+09, 1e+09, 1e+09) lies far from the rest"), std::string::npos) << r.output;
  EXPECT_EQ(count_lines(r.output), 1u) << r.output;
}

TEST(SynthLimits, SliverSwatchIsRefused) {
  const auto dir = scratch_dir("synth_sliver");
  write_file(dir / "sliver.off",
             "OFF\n4 4 0\n0 0 0\n1e7 0 0\n0 1 0\n0 0 0.3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const CliResult r = run_cli("synth --progress none --swatch '" + (dir / "sliver.off").string() + "' -o '" +
                              (dir / "o.ply").string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.output;
  // Its faces are lower than the weld tolerance of a box 1e7 across: refused for having no area.
  EXPECT_TRUE(r.output.find("aspect") != std::string::npos || r.output.find("no face has area") != std::string::npos)
      << r.output;
  EXPECT_EQ(count_lines(r.output), 1u) << r.output;
}

TEST(SynthLimits, CoordinateBeyondRangeIsRefused) {
  const auto dir = scratch_dir("synth_far");
  write_file(dir / "far.off",
             "OFF\n4 4 0\n1e20 1e20 1e20\n1.1e20 1e20 1e20\n1e20 1.1e20 1e20\n1e20 1e20 1.03e20\n"
             "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const CliResult r = run_cli("synth --progress none --swatch '" + (dir / "far.off").string() + "' -o '" +
                              (dir / "o.ply").string() + "'");
  EXPECT_EQ(r.exit_code, 5) << r.output;
  EXPECT_NE(r.output.find("beyond +-1e15"), std::string::npos) << r.output;
}

// Peak RSS of the whole process for a refused hostile header, against a tiny valid file.
TEST(ReaderLimitsCli, HostileHeadersStayWithinAFewMegabytes) {
  const auto dir = scratch_dir("reader_rss");
  write_file(dir / "ok.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0.3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2147483648\nproperty list uchar int vertex_indices\nend_header\n";
  ply.resize(1024, '\0');
  write_file(dir / "huge.ply", ply);
  write_file(dir / "big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1099511627776\n");
  write_file(dir / "neg.off", "OFF\n-1 -1 0\n");
  const ChildEnd base = wait_child(spawn_cli({"inspect", (dir / "ok.off").string()}));
  ASSERT_EQ(base.exit_code, 0);
  for (const char* name : {"huge.ply", "big.obj", "neg.off"}) {
    const ChildEnd end = wait_child(spawn_cli({"inspect", (dir / name).string()}, (dir / "log.txt").string()));
    const std::string log = read_file(dir / "log.txt");
    EXPECT_EQ(end.exit_code, 5) << name << ": " << log;
    EXPECT_EQ(count_lines(log), 1u) << log;
    EXPECT_LT(end.peak_rss_kib, base.peak_rss_kib + 8 * 1024) << name << " peak " << end.peak_rss_kib << " KiB, base "
                                                              << base.peak_rss_kib << " KiB";
  }
}

// SIGKILL at random moments while `swatch` writes a large mesh over an existing one: the file
// is always the old one or the complete new one, byte for byte.
TEST(CrashSafeWrites, SigkillDuringALargeWrite) {
  const auto dir = scratch_dir("sigkill_write");
  const std::vector<std::string> big = {"swatch", "chainmail", "--rows", "40", "--columns", "40", "--ascii"};
  auto with_output = [&](std::vector<std::string> args, const std::filesystem::path& out) {
    args.push_back("-o");
    args.push_back(out.string());
    return args;
  };
  // The complete new content, and how long writing it takes.
  const auto t0 = Clock::now();
  ASSERT_EQ(wait_child(spawn_cli(with_output(big, dir / "reference.ply"))).exit_code, 0);
  const double full = std::chrono::duration<double>(Clock::now() - t0).count();
  const std::string fresh = read_file(dir / "reference.ply");
  ASSERT_GT(fresh.size(), 20u << 20) << "expected a large output";
  ASSERT_EQ(run_cli("swatch chainmail --preset small -o '" + (dir / "out.ply").string() + "'").exit_code, 0);
  const std::string old = read_file(dir / "out.ply");

  std::mt19937 random(12345);
  std::uniform_real_distribution<double> moment(0.0, full * 1.1);
  int kept_old = 0, complete_new = 0;
  constexpr int kKills = 25;
  for (int i = 0; i < kKills; ++i) {
    const pid_t pid = spawn_cli(with_output(big, dir / "out.ply"));
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
    kill(pid, SIGKILL);
    wait_child(pid);
    const std::string now = read_file(dir / "out.ply");
    if (now == old) {
      ++kept_old;
    } else {
      ASSERT_EQ(now.size(), fresh.size()) << "kill " << i << " left a partial file";
      ASSERT_TRUE(now == fresh) << "kill " << i << " left a corrupt file";
      ++complete_new;
      write_file(dir / "out.ply", old);  // the next kill must again find the old file
    }
    for (const std::string& t : temporaries(dir)) std::filesystem::remove(dir / t);  // SIGKILL cannot clean up
  }
  EXPECT_GT(kept_old, 0);
  std::cout << kKills << " kills: old file kept " << kept_old << ", complete new file " << complete_new << "\n";
}

// The same through `synth`: kills over the whole run, including its write.
TEST(CrashSafeWrites, SigkillDuringSynth) {
  const auto dir = scratch_dir("sigkill_synth");
  const std::vector<std::string> job = {"synth", "--progress", "none", "--plane", "1x1", "--backend", "cpu", "-o"};
  auto run_to = [&](const std::filesystem::path& out) {
    auto args = job;
    args.push_back(out.string());
    return spawn_cli(args);
  };
  const auto t0 = Clock::now();
  ASSERT_EQ(wait_child(run_to(dir / "reference.ply")).exit_code, 0);
  const double full = std::chrono::duration<double>(Clock::now() - t0).count();
  const std::string fresh = read_file(dir / "reference.ply");
  write_file(dir / "out.ply", "previous good output");
  std::mt19937 random(777);
  // Most kills land near the end, where the output is written.
  std::uniform_real_distribution<double> moment(full * 0.6, full * 1.05);
  for (int i = 0; i < 8; ++i) {
    const pid_t pid = run_to(dir / "out.ply");
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
    kill(pid, SIGKILL);
    wait_child(pid);
    const std::string now = read_file(dir / "out.ply");
    ASSERT_TRUE(now == "previous good output" || now == fresh) << "kill " << i << ": " << now.size() << " bytes";
    write_file(dir / "out.ply", "previous good output");
    for (const std::string& t : temporaries(dir)) std::filesystem::remove(dir / t);
  }
}

// `job` (a command and its options): one of tens of seconds, so that the signal lands mid-run on
// the fastest machine (every ring through the patch step: a filled plane is done in a second).
void expect_interrupt(int signal_number, const char* name, std::vector<std::string> job) {
  const auto dir = scratch_dir(name);
  write_file(dir / "out.ply", "previous good output");
  write_file(dir / "stats.json", "previous stats");
  for (const std::string& arg : {"--progress", "none", "--backend", "cpu", "--stats"}) job.push_back(arg);
  job.push_back((dir / "stats.json").string());
  job.push_back("-o");
  job.push_back((dir / "out.ply").string());
  const pid_t pid = spawn_cli(job, (dir / "log.txt").string());
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, signal_number);
  const auto sent = Clock::now();
  const ChildEnd end = wait_at_most(pid, 120.0);
  const double seconds = std::chrono::duration<double>(Clock::now() - sent).count();
  const std::string log = read_file(dir / "log.txt");
  EXPECT_EQ(end.exit_code, 10) << log;
  EXPECT_NE(log.find("meshquilt: interrupted"), std::string::npos) << log;
  EXPECT_EQ(read_file(dir / "out.ply"), "previous good output");
  EXPECT_EQ(read_file(dir / "stats.json"), "previous stats");
  EXPECT_TRUE(temporaries(dir).empty());
  std::cout << name << ": stopped " << seconds << " s after the signal\n";
}

TEST(Interrupts, SigintLeavesTheOldOutput) { expect_interrupt(SIGINT, "sigint", {"synth", "--plane", "10x10", "--fill-margin", "0"}); }
TEST(Interrupts, SigtermLeavesTheOldOutput) { expect_interrupt(SIGTERM, "sigterm", {"synth", "--plane", "10x10", "--fill-margin", "0"}); }
TEST(Interrupts, SigtermStopsPaint) {
  const std::string data = std::string(MESHQUILT_SOURCE_DIR) + "/data/";
  expect_interrupt(SIGTERM, "sigterm_paint",
                   {"paint", "--base", data + "sphere.off", "--image", data + "bricks.ppm", "--scale", "0.1"});
}

}  // namespace
}  // namespace meshquilt::test
