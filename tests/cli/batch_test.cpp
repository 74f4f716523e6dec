// `meshquilt batch` end to end: a manifest of small planar jobs sharded across three processes
// matches direct `synth` runs byte for byte, as paint and relief jobs match theirs; a batch killed with SIGKILL in the middle of a job
// resumes without redoing finished jobs; bad manifests get one line naming the manifest line;
// Slurm array variables pick the shard.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "support/run_cli.h"
#include "support/spawn.h"

namespace meshquilt::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct TestJob {
  const char* output;   // relative to the manifest's folder
  const char* options;  // synth's options as a JSON list or object (swatches: chain.ply, twill.ply)
};

// ---- The jobs every batch test runs. ------------------------------------------------------
// Curved-surface jobs cover the shipped sphere (copied beside the manifest). --max-patches keeps each job to a
// fraction of a second; job 2 is the largest (about 0.9 s), so the kill test, 300 ms after it
// starts, stops the batch while it runs.
const TestJob kJobs[] = {
    {"out/chain1.ply", R"(["--swatch", "chain.ply", "--plane", "1x1", "--seed", 1, "--backend", "cpu", "--max-patches", 3])"},
    {"out/twill2.ply", R"(["--swatch", "twill.ply", "--plane", "1x1", "--seed", 2, "--backend", "cpu", "--max-patches", 3])"},
    {"out/chain3.ply", R"({"swatch": "chain.ply", "plane": "3x3", "seed": 3, "backend": "cpu", "max-patches": 60, "stats": "out/chain3.json"})"},
    {"out/twill4.obj", R"(["--swatch", "twill.ply", "--plane", "1x1", "--seed", 4, "--backend", "cpu", "--max-patches", 3])"},
    {"out/builtin5.ply", R"(["--plane", "1x1", "--seed", 5, "--backend", "cpu", "--max-patches", 3])"},
    {"out/chain6.off", R"({"swatch": "chain.ply", "plane": "1x1.5", "seed": 6, "backend": "cpu", "max-patches": 3})"},
    {"out/twill7.stl", R"(["--swatch", "twill.ply", "--plane", "1.5x1", "--seed", 7, "--backend", "cpu", "--cells", 12, "--max-patches", 3])"},
    {"out/chain8.ply", R"(["--swatch", "chain.ply", "--plane", "1x1", "--seed", 8, "--backend", "cpu", "--no-cleanup", "--max-patches", 3])"},
    {"out/sphere9.ply", R"(["--swatch", "chain.ply", "--base", "sphere.off", "--scale", 0.3, "--seed", 9, "--backend", "cpu", "--max-patches", 3])"},
    {"out/sphere10.ply", R"({"swatch": "twill.ply", "base": "sphere.off", "scale": 0.4, "seed": 10, "backend": "cpu", "max-patches": 2})"},
};
// ---------------------------------------------------------------------------------------------
constexpr size_t kJobCount = sizeof(kJobs) / sizeof(kJobs[0]);

std::string quote(const fs::path& path) { return "'" + path.string() + "'"; }

CliResult run_shell(const std::string& command) {
  CliResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// Runs `meshquilt ARGS` in `dir` (so relative paths resolve there) after `environment`
// assignments; stderr merged into stdout.
CliResult meshquilt_in(const fs::path& dir, const std::string& args, const std::string& environment = "") {
  return run_shell("cd " + quote(dir) + " && " + environment + " '" + MESHQUILT_CLI + "' " + args);
}

std::string manifest_text() {
  std::string text = "# batch_test manifest: one job a line\n";
  for (const TestJob& job : kJobs)
    text += std::string("{\"output\": \"") + job.output + "\", \"options\": " + job.options + "}\n";
  return text;
}

// The job's options as synth arguments, for a direct run (a tiny reader for kJobs' own JSON).
std::string direct_arguments(const TestJob& job) {
  std::string text = job.options, args;
  const bool object = text[0] == '{';
  std::string token;
  bool in_string = false, is_key = true;
  auto flush = [&](bool quoted) {
    if (token.empty() && !quoted) return;
    if (object && is_key) args += " --" + token;
    else args += " '" + token + "'";
    if (object) is_key = !is_key;
    token.clear();
  };
  for (char c : text) {
    if (in_string) {
      if (c == '"') { in_string = false; flush(true); }
      else token += c;
    } else if (c == '"') {
      in_string = true;
    } else if (c == ',' || c == ']' || c == '}' || c == ':' || c == ' ') {
      if (!token.empty()) flush(false);
    } else if (c != '[' && c != '{') {
      token += c;
    }
  }
  return args;
}

struct FileStamp {
  ino_t inode = 0;
  long long mtime_ns = 0;
  bool operator==(const FileStamp&) const = default;
};

FileStamp stamp(const fs::path& file) {
  struct stat s {};
  if (::stat(file.c_str(), &s) != 0) return {};
  return {s.st_ino, static_cast<long long>(s.st_mtim.tv_sec) * 1000000000LL + s.st_mtim.tv_nsec};
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class BatchTest : public ::testing::Test {
 protected:
  // Swatches and the direct synth output of every job, made once.
  static void SetUpTestSuite() {
    const auto start = Clock::now();
    source_ = scratch_dir("batch_source_" + std::to_string(getpid()));  // one per test process
    ASSERT_EQ(run_cli("swatch chainmail --preset small -o " + quote(source_ / "chain.ply")).exit_code, 0);
    ASSERT_EQ(run_cli("swatch weave --pattern twill:2/3 --preset small -o " + quote(source_ / "twill.ply")).exit_code, 0);
    fs::copy_file(fs::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off", source_ / "sphere.off",
                  fs::copy_options::overwrite_existing);
    fs::create_directories(source_ / "direct" / "out");
    for (const TestJob& job : kJobs) {
      std::string args = direct_arguments(job);
      // Stats of the direct run go beside its outputs, not over the batch's.
      const size_t stats = args.find("'out/");
      if (stats != std::string::npos) args.replace(stats, 5, "'direct/out/");
      const CliResult r = meshquilt_in(source_, "synth" + args + " --progress none -o 'direct/" + job.output + "'");
      ASSERT_EQ(r.exit_code, 0) << job.output << ": " << r.output;
    }
    std::printf("direct synth of %zu jobs: %.1f s\n", kJobCount,
                std::chrono::duration<double>(Clock::now() - start).count());
  }

  // A fresh folder holding the swatches and the manifest.
  static fs::path fresh_batch(const std::string& name) {
    const fs::path dir = scratch_dir(name);
    fs::copy_file(source_ / "chain.ply", dir / "chain.ply");
    fs::copy_file(source_ / "twill.ply", dir / "twill.ply");
    fs::copy_file(fs::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off", dir / "sphere.off");
    write_file(dir / "jobs.jsonl", manifest_text());
    return dir;
  }

  static void expect_outputs_match_direct(const fs::path& dir) {
    for (const TestJob& job : kJobs) {
      const std::string made = read_file(dir / job.output);
      EXPECT_FALSE(made.empty()) << job.output;
      EXPECT_TRUE(made == read_file(source_ / "direct" / job.output)) << job.output << " differs from direct synth";
    }
  }

  static inline fs::path source_;
};

TEST_F(BatchTest, ThreeShardsMatchDirectSynth) {
  const fs::path dir = fresh_batch("batch_shards");
  const auto start = Clock::now();
  std::vector<pid_t> shards;
  for (int i = 0; i < 3; ++i)
    shards.push_back(spawn_cli({"batch", (dir / "jobs.jsonl").string(), "--shard", std::to_string(i) + "/3",
                                "--threads", "1", "--progress", "json"},
                               (dir / ("shard" + std::to_string(i) + ".log")).string()));
  for (int i = 0; i < 3; ++i) {
    const ChildEnd end = wait_child(shards[i]);
    const std::string log = read_file(dir / ("shard" + std::to_string(i) + ".log"));
    EXPECT_EQ(end.exit_code, 0) << log;
    EXPECT_EQ(count_of(log, "\"event\":\"job_end\""), (kJobCount - i + 2) / 3) << log;  // jobs i, i+3, ...
    EXPECT_NE(log.find("\"shard\":\"" + std::to_string(i) + "/3\""), std::string::npos) << log;
  }
  std::printf("3 shards, %zu jobs: %.1f s\n", kJobCount, std::chrono::duration<double>(Clock::now() - start).count());
  expect_outputs_match_direct(dir);

  const CliResult report = run_cli("batch " + quote(dir / "jobs.jsonl") + " --report --format csv");
  EXPECT_EQ(report.exit_code, 0) << report.output;
  EXPECT_EQ(count_of(report.output, ",done,"), kJobCount) << report.output;
  const CliResult table = run_cli("batch " + quote(dir / "jobs.jsonl") + " --report");
  EXPECT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find(std::to_string(kJobCount) + " done, 0 failed, 0 running, 0 missing"), std::string::npos)
      << table.output;

  // A rerun finds every record matching and runs nothing.
  const CliResult again = run_cli("batch " + quote(dir / "jobs.jsonl") + " --progress json");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(count_of(again.output, "\"reason\":\"done\""), kJobCount) << again.output;
  EXPECT_EQ(count_of(again.output, "\"event\":\"job_start\""), 0u) << again.output;
}

// Waits until `log` holds `count` copies of `what`, at most `seconds`.
bool wait_for(const fs::path& log, const std::string& what, size_t count, double seconds) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < deadline) {
    if (count_of(read_file(log), what) >= count) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Processes whose command line mentions `text`, other than this one.
std::vector<std::string> processes_mentioning(const std::string& text) {
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos || std::stoi(pid) == getpid()) continue;
    std::string cmdline = read_file(entry.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (cmdline.find(text) != std::string::npos && cmdline.find("synth") != std::string::npos)
      found.push_back(pid + ": " + cmdline);
  }
  return found;
}

TEST_F(BatchTest, SigkillMidJobThenRerunRedoesOnlyUnfinishedJobs) {
  const fs::path dir = fresh_batch("batch_kill");
  const fs::path log = dir / "first.log";
  const pid_t batch = spawn_cli({"batch", (dir / "jobs.jsonl").string(), "--progress", "json"}, log.string());
  // Two jobs finished and the third (the largest) started: kill the batch in the middle of it.
  ASSERT_TRUE(wait_for(log, "\"event\":\"job_start\"", 3, 300.0)) << read_file(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(batch, SIGKILL);
  wait_child(batch);
  const std::string first = read_file(log);
  const size_t logged = count_of(first, "\"status\":\"done\"");

  // The running synth died with the batch (PR_SET_PDEATHSIG): nothing writes behind the rerun.
  std::vector<std::string> orphans;
  for (int i = 0; i < 50; ++i) {
    orphans = processes_mentioning(dir.string());
    if (orphans.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_TRUE(orphans.empty()) << orphans.front();

  std::vector<FileStamp> before;
  for (const TestJob& job : kJobs) before.push_back(stamp(dir / job.output));
  // The records decide what is done: a job whose record was written when the kill came, before
  // its progress line, is done but not logged.
  const CliResult partial = run_cli("batch " + quote(dir / "jobs.jsonl") + " --report --format csv");
  EXPECT_EQ(partial.exit_code, 13) << partial.output;
  const size_t finished = count_of(partial.output, ",done,");
  EXPECT_TRUE(finished == logged || finished == logged + 1) << partial.output << first;
  EXPECT_GE(finished, 2u) << first;
  EXPECT_LT(finished, kJobCount) << first;

  const CliResult rerun = run_cli("batch " + quote(dir / "jobs.jsonl") + " --progress json");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_EQ(count_of(rerun.output, "\"reason\":\"done\""), finished) << rerun.output;
  EXPECT_EQ(count_of(rerun.output, "\"status\":\"done\""), kJobCount - finished) << rerun.output;
  size_t untouched = 0;
  for (size_t i = 0; i < kJobCount; ++i)
    if (before[i].inode != 0 && stamp(dir / kJobs[i].output) == before[i]) ++untouched;
  EXPECT_EQ(untouched, finished) << "finished jobs must not be rewritten";
  expect_outputs_match_direct(dir);
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();

  const CliResult report = run_cli("batch " + quote(dir / "jobs.jsonl") + " --report --format json");
  EXPECT_EQ(report.exit_code, 0) << report.output;
  EXPECT_NE(report.output.find("\"done\": " + std::to_string(kJobCount)), std::string::npos) << report.output;
}

TEST(BatchManifest, MissingManifestIsOneLine) {
  const fs::path dir = scratch_dir("batch_missing");
  const CliResult r = run_cli("batch " + quote(dir / "nope.jsonl"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("nope.jsonl: cannot open"), std::string::npos) << r.output;
  EXPECT_EQ(count_of(r.output, "\n"), 1u) << r.output;
}

struct BadManifest {
  const char* name;
  const char* text;
  const char* expected;  // in the one-line message
};

class BatchBadManifest : public ::testing::TestWithParam<BadManifest> {};

TEST_P(BatchBadManifest, IsRefusedWithOneLineNamingTheLine) {
  const BadManifest& bad = GetParam();
  const fs::path dir = scratch_dir(std::string("batch_bad_") + bad.name);
  const fs::path manifest = dir / (bad.name + std::string(bad.name[0] == 'j' ? ".json" : ".jsonl"));
  write_file(manifest, bad.text);
  for (const char* mode : {"", " --report", " --count"}) {
    const CliResult r = run_cli("batch " + quote(manifest) + mode);
    EXPECT_EQ(r.exit_code, 12) << mode << ": " << r.output;
    EXPECT_NE(r.output.find(bad.expected), std::string::npos) << r.output;
    EXPECT_EQ(count_of(r.output, "\n"), 1u) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out")) << "nothing runs from a bad manifest";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BatchBadManifest,
    ::testing::Values(
        BadManifest{"unknown_option",
                    "{\"output\": \"out/a.ply\", \"options\": [\"--plane\", \"1x1\"]}\n\n"
                    "{\"output\": \"out/b.ply\", \"options\": [\"--frobnicate\", 3]}\n",
                    "unknown_option.jsonl:3: The following arguments were not expected: 3 --frobnicate"},
        BadManifest{"unknown_key_option",
                    "{\"output\": \"out/a.ply\", \"options\": {\"plane\": \"1x1\", \"colour\": \"red\"}}\n",
                    "unknown_key_option.jsonl:1: The following arguments were not expected: red --colour"},
        BadManifest{"duplicate_output",
                    "{\"output\": \"out/a.ply\", \"options\": [\"--seed\", 1]}\n"
                    "{\"output\": \"out/b.ply\", \"options\": [\"--seed\", 2]}\n"
                    "{\"output\": \"out/../out/a.ply\", \"options\": [\"--seed\", 3]}\n",
                    "duplicate_output.jsonl:3: out/../out/a.ply is also written by the job on line 1"},
        BadManifest{"duplicate_stats",
                    "{\"output\": \"out/a.ply\", \"options\": [\"--stats\", \"s.json\"]}\n"
                    "{\"output\": \"out/b.ply\", \"options\": [\"--stats\", \"s.json\"]}\n",
                    "duplicate_stats.jsonl:2: s.json is also written by the job on line 1"},
        BadManifest{"output_in_options", "{\"output\": \"a.ply\", \"options\": [\"-o\", \"b.ply\"]}\n",
                    "output_in_options.jsonl:1: give the output as the job's \"output\""},
        BadManifest{"no_output", "{\"options\": [\"--seed\", 1]}\n", "no_output.jsonl:1: \"output\": expected"},
        BadManifest{"not_json", "{\"output\": \"a.ply\"}\n{\"output\": \"b.ply\",\n", "not_json.jsonl:2: not a JSON object"},
        BadManifest{"bad_value", "{\"output\": \"a.ply\", \"options\": [\"--seed\", \"many\"]}\n",
                    "bad_value.jsonl:1: Could not convert: --seed = many"},
        BadManifest{"json_unknown_option",
                    "[\n  {\"output\": \"a.ply\", \"options\": [\"--seed\", 1]},\n\n"
                    "  {\"output\": \"b.ply\",\n   \"options\": [\"--nope\"]}\n]\n",
                    "json_unknown_option.json:4: The following argument was not expected: --nope"},
        BadManifest{"unknown_command",
                    "{\"output\": \"a.ply\", \"options\": [\"--seed\", 1]}\n"
                    "{\"command\": \"colour\", \"output\": \"b.ply\"}\n",
                    "unknown_command.jsonl:2: \"command\": expected synth, paint, relief or loom, got 'colour'"},
        BadManifest{"paint_without_image",
                    "{\"command\": \"paint\", \"output\": \"a.ply\", \"options\": {\"base\": \"b.off\"}}\n",
                    "paint_without_image.jsonl:1: --image is required"},
        BadManifest{"relief_unknown_option",
                    "{\"command\": \"relief\", \"output\": \"a.ply\", \"options\": [\"--base\", \"b.off\", "
                    "\"--plane\", \"1x1\"]}\n",
                    "relief_unknown_option.jsonl:1: The following arguments were not expected: 1x1 --plane"},
        BadManifest{"relief_image_without_height",
                    "{\"command\": \"relief\", \"output\": \"a.ply\", \"options\": {\"base\": \"b.off\", "
                    "\"image\": \"h.pgm\"}}\n",
                    "relief_image_without_height.jsonl:1: --height: required with --image"},
        BadManifest{"relief_without_sample",
                    "{\"command\": \"relief\", \"output\": \"a.ply\", \"options\": {\"base\": \"b.off\"}}\n",
                    "relief_without_sample.jsonl:1: relief: expected one of --image and --from"},
        BadManifest{"json_duplicate", "{\"jobs\": [\n{\"output\": \"a.ply\"},\n{\"output\": \"a.ply\"}]}\n",
                    "json_duplicate.json:3: a.ply is also written by the job on line 2"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(BatchManifest, JobWithMissingSwatchIsRecordedAndTheOthersRun) {
  const fs::path dir = scratch_dir("batch_missing_swatch");
  ASSERT_EQ(run_cli("swatch chainmail --preset small -o " + quote(dir / "chain.ply")).exit_code, 0);
  write_file(dir / "jobs.jsonl",
             "{\"output\": \"out/a.ply\", \"options\": [\"--swatch\", \"chain.ply\", \"--plane\", \"1x1\", \"--max-patches\", 2]}\n"
             "{\"output\": \"out/b.ply\", \"options\": [\"--swatch\", \"nope.ply\", \"--plane\", \"1x1\"]}\n"
             "{\"output\": \"out/c.ply\", \"options\": [\"--swatch\", \"chain.ply\", \"--plane\", \"1x1\", \"--seed\", 4, \"--max-patches\", 2]}\n");
  const CliResult r = run_cli("batch " + quote(dir / "jobs.jsonl") + " --progress none");
  EXPECT_EQ(r.exit_code, 13) << r.output;
  EXPECT_NE(r.output.find("jobs.jsonl:2: nope.ply: cannot open: No such file or directory"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(dir / "out/a.ply"));
  EXPECT_TRUE(fs::exists(dir / "out/c.ply"));
  const CliResult report = run_cli("batch " + quote(dir / "jobs.jsonl") + " --report --format csv");
  EXPECT_EQ(report.exit_code, 13) << report.output;
  EXPECT_EQ(count_of(report.output, ",done,"), 2u) << report.output;
  EXPECT_NE(report.output.find("1,2,out/b.ply,failed,"), std::string::npos) << report.output;
  EXPECT_NE(report.output.find("1 of 3 jobs not done (1 failed"), std::string::npos) << report.output;
}

// Paint and relief jobs run beside synth's: each output is byte-identical to a direct run of its
// command, a rerun skips them all, and a changed sample redoes only the job that reads it.
TEST(BatchCommands, PaintAndReliefJobsMatchDirectRuns) {
  const fs::path dir = scratch_dir("batch_paint_relief");
  fs::copy_file(fs::path(MESHQUILT_SOURCE_DIR) / "data/sphere.off", dir / "sphere.off");
  std::string ppm = "P3\n8 8\n255\n", pgm = "P2\n8 8\n255\n";
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      ppm += std::to_string(32 * x) + " " + std::to_string(255 - 32 * y) + " " + std::to_string((x * y) % 7 * 36) + "\n";
      pgm += std::to_string(((x / 2 + y / 2) % 2) * 255) + "\n";
    }
  write_file(dir / "sample.ppm", ppm);
  write_file(dir / "heights.pgm", pgm);
  write_file(dir / "jobs.jsonl",
             "{\"command\": \"paint\", \"output\": \"out/painted.ply\", \"options\": {\"base\": \"sphere.off\", "
             "\"image\": \"sample.ppm\", \"scale\": 0.5, \"backend\": \"cpu\", \"stats\": \"out/painted.json\"}}\n"
             "{\"command\": \"relief\", \"output\": \"out/raised.ply\", \"options\": [\"--base\", \"sphere.off\", "
             "\"--image\", \"heights.pgm\", \"--height\", 0.05, \"--scale\", 0.5, \"--backend\", \"cpu\"]}\n"
             "{\"command\": \"synth\", \"output\": \"out/chain.ply\", \"options\": [\"--plane\", \"1x1\", "
             "\"--max-patches\", 2, \"--backend\", \"cpu\"]}\n");
  const CliResult r = meshquilt_in(dir, "batch jobs.jsonl --progress none");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("jobs.jsonl:1 out/painted.ply: 1280 faces, 642 vertices"), std::string::npos) << r.output;

  ASSERT_EQ(meshquilt_in(dir, "paint --base sphere.off --image sample.ppm --scale 0.5 --backend cpu --progress none "
                              "-o direct_painted.ply").exit_code, 0);
  ASSERT_EQ(meshquilt_in(dir, "relief --base sphere.off --image heights.pgm --height 0.05 --scale 0.5 --backend cpu "
                              "--progress none -o direct_raised.ply").exit_code, 0);
  EXPECT_FALSE(read_file(dir / "out/painted.ply").empty());
  EXPECT_TRUE(read_file(dir / "out/painted.ply") == read_file(dir / "direct_painted.ply")) << "paint differs";
  EXPECT_TRUE(read_file(dir / "out/raised.ply") == read_file(dir / "direct_raised.ply")) << "relief differs";
  EXPECT_NE(read_file(dir / "out/painted.json").find("\"pixels_per_unit\""), std::string::npos);

  const CliResult report = meshquilt_in(dir, "batch jobs.jsonl --report --format csv");
  EXPECT_EQ(report.exit_code, 0) << report.output;
  EXPECT_EQ(count_of(report.output, ",done,"), 3u) << report.output;
  const CliResult json_report = meshquilt_in(dir, "batch jobs.jsonl --report --format json");
  EXPECT_NE(json_report.output.find("\"command\": \"relief\""), std::string::npos) << json_report.output;
  EXPECT_NE(meshquilt_in(dir, "batch jobs.jsonl --progress none").output.find("0 done, 3 already done"),
            std::string::npos);

  write_file(dir / "sample.ppm", "P3\n8 8\n255\n1" + ppm.substr(12));  // the first red value, 0, made 1
  const CliResult again = meshquilt_in(dir, "batch jobs.jsonl --progress none");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("1 done, 2 already done"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("out/painted.ply"), std::string::npos) << again.output;
}

// A loom job runs as its command does: the same bytes, its faces in the finished line, its
// exemplars and design among the files that redo it when changed.
TEST(BatchCommands, LoomJobsMatchDirectRuns) {
  const fs::path dir = scratch_dir("batch_loom");
  ASSERT_EQ(meshquilt_in(dir, "swatch weave --pattern twill:2/2 --warps 8 --wefts 8 -o twill.ply").exit_code, 0);
  write_file(dir / "design.pbm", "P1\n6 4\n110011\n100110\n001100\n011001\n");
  write_file(dir / "jobs.jsonl",
             "{\"command\": \"loom\", \"output\": \"out/fabric.ply\", \"options\": {\"design\": \"design.pbm\", "
             "\"exemplar\": \"twill.ply\", \"stations\": 4, \"sides\": 5, \"stats\": \"out/fabric.json\"}}\n");
  const CliResult r = meshquilt_in(dir, "batch jobs.jsonl --progress none");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_EQ(meshquilt_in(dir, "loom --design design.pbm --exemplar twill.ply --stations 4 --sides 5 --progress none "
                              "-o direct.ply").exit_code, 0);
  EXPECT_FALSE(read_file(dir / "out/fabric.ply").empty());
  EXPECT_TRUE(read_file(dir / "out/fabric.ply") == read_file(dir / "direct.ply")) << "loom differs";
  EXPECT_NE(r.output.find("out/fabric.ply: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" 10 elements"), std::string::npos) << r.output;
  EXPECT_NE(read_file(dir / "out/fabric.json").find("\"grid\""), std::string::npos);
  EXPECT_NE(meshquilt_in(dir, "batch jobs.jsonl --progress none").output.find("0 done, 1 already done"),
            std::string::npos);
  write_file(dir / "design.pbm", "P1\n6 4\n110011\n100110\n001100\n011000\n");
  EXPECT_NE(meshquilt_in(dir, "batch jobs.jsonl --progress none").output.find("1 done, 0 already done"),
            std::string::npos);
}

TEST(BatchShard, SlurmArrayVariablesPickTheShard) {
  const fs::path dir = scratch_dir("batch_slurm_env");
  std::string manifest;
  for (int i = 0; i < 6; ++i)  // jobs that fail before any synth starts: fast
    manifest += "{\"output\": \"o" + std::to_string(i) + ".ply\", \"options\": [\"--swatch\", \"none.ply\"]}\n";
  write_file(dir / "jobs.jsonl", manifest);
  // An array --array=1-7:2 has tasks 1, 3, 5, 7: task 5 is shard 2 of 4, which holds job 2 only.
  const CliResult r = meshquilt_in(dir, "batch jobs.jsonl --progress json",
                                   "SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_STEP=2 "
                                   "SLURM_ARRAY_TASK_COUNT=4");
  EXPECT_EQ(r.exit_code, 13) << r.output;
  EXPECT_NE(r.output.find("\"shard\":\"2/4\""), std::string::npos) << r.output;
  EXPECT_EQ(count_of(r.output, "\"event\":\"job_end\""), 1u) << r.output;
  EXPECT_NE(r.output.find("\"output\":\"o2.ply\""), std::string::npos) << r.output;
  // --shard wins over the environment; a task id outside the array is an error.
  const CliResult forced = meshquilt_in(dir, "batch jobs.jsonl --progress json --shard 1/2", "SLURM_ARRAY_TASK_ID=5");
  EXPECT_NE(forced.output.find("\"shard\":\"1/2\""), std::string::npos) << forced.output;
  const CliResult odd = meshquilt_in(dir, "batch jobs.jsonl", "SLURM_ARRAY_TASK_ID=4 SLURM_ARRAY_TASK_MIN=1 "
                                     "SLURM_ARRAY_TASK_STEP=2 SLURM_ARRAY_TASK_COUNT=4");
  EXPECT_EQ(odd.exit_code, 6) << odd.output;
  const CliResult bad = run_cli("batch " + quote(dir / "jobs.jsonl") + " --shard 3/3");
  EXPECT_EQ(bad.exit_code, 6) << bad.output;
  EXPECT_NE(bad.output.find("--shard: expected I/N"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace meshquilt::test
