// Reproduces rows of Table 1 of the mesh quilting paper with our closest swatches: for each
// scenario and back end, runs `meshquilt synth` several times in a child process and prints our
// median seconds, the paper's, their ratio, faces per second, peak memory and the share of time
// per stage, as a Markdown table. Planar rows size the plane, curved rows the --scale over the
// base, for about the paper's output faces.
//
//   table1_runner [--runs N] [--backends cpu,vulkan] [--scenarios wire,apple,bunny-weave,bunny-link]
//                 [--scale F] [--shared DIR]
//
// --scale multiplies the output faces (0.1 for a quick look); --shared is where data/meshes/
// holds the curved rows' bases (default: ../shared beside the source tree).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "run_child.h"
#include "split_list.h"

#include <nlohmann/json.hpp>

namespace {

struct Scenario {
  std::string key;           // command-line name
  std::string paper_row;     // Table 1 row
  double paper_seconds;      // Table 1 time
  long paper_faces;          // Table 1 output faces
  std::string swatch_args;   // `meshquilt swatch` arguments of our closest swatch
  std::string base;          // base mesh under <shared>/data/meshes; empty: a plane
};

const std::vector<Scenario> kScenarios = {
    {"wire", "Plane + Wire", 3 * 60.0, 74792, "chainmail --rows 8 --columns 6", ""},
    {"apple", "Plane + Apple", 3 * 60.0, 321000, "fruit --columns 5 --rows 5 --subdivisions 2", ""},
    {"bunny-weave", "Bunny + Weave", 86 * 60.0, 700815, "weave", "bunny.off"},
    {"bunny-link", "Bunny + Link", 80 * 60.0, 940622, "chainmail --rows 8 --columns 6", "bunny.off"},
};

struct Run {
  double seconds = 0.0;
  long faces = 0;
  long peak_kib = 0;
  std::map<std::string, double> stages;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  double scale = 1.0;
  std::vector<std::string> backends = {"cpu", "vulkan"};
  std::vector<std::string> scenarios = {"wire", "apple", "bunny-weave", "bunny-link"};
  std::filesystem::path shared = std::filesystem::path(MESHQUILT_SOURCE_DIR) / ".." / "shared";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--runs") runs = std::max(1, std::stoi(value));
    else if (flag == "--backends") backends = meshquilt::perf::split(value, ',');
    else if (flag == "--scenarios") scenarios = meshquilt::perf::split(value, ',');
    else if (flag == "--scale") scale = std::stod(value);
    else if (flag == "--shared") shared = value;
    else {
      std::fprintf(stderr, "table1_runner: unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  const std::string cli = MESHQUILT_CLI;
  const auto work = std::filesystem::temp_directory_path() / ("meshquilt_table1_" + std::to_string(getpid()));
  std::filesystem::create_directories(work);

  std::printf("| scenario | backend | faces out | ours (s, median of %d) | paper (s) | ours / paper | faces/s | peak MiB | main stages |\n", runs);
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Scenario& sc : kScenarios) {
    if (std::find(scenarios.begin(), scenarios.end(), sc.key) == scenarios.end()) continue;
    const auto swatch = work / (sc.key + ".ply");
    std::vector<std::string> make = {cli, "swatch"};
    for (const auto& a : meshquilt::perf::split(sc.swatch_args, ' ')) make.push_back(a);
    make.insert(make.end(), {"-o", swatch.string()});
    if (meshquilt::perf::run_child(make) != 0) {
      std::fprintf(stderr, "table1_runner: making the %s swatch failed\n", sc.key.c_str());
      return 1;
    }
    // The domain: a plane sized, or a base at a --scale, for about the paper's output size
    // (faces grow with the area, or with 1 / scale^2), from a probe run.
    std::vector<std::string> domain;
    const auto base = shared / "data" / "meshes" / sc.base;
    if (!sc.base.empty() && !std::filesystem::exists(base)) {
      std::fprintf(stderr, "table1_runner: %s not found (--shared DIR); skipping %s\n", base.c_str(), sc.key.c_str());
      continue;
    }
    const double probe_scale = 0.2;
    char size[64];
    if (sc.base.empty()) {
      domain = {"--plane", "1x1"};
    } else {
      std::snprintf(size, sizeof size, "%.2f", probe_scale);
      domain = {"--base", base.string(), "--scale", size};
    }
    const auto probe = work / "probe.json";
    std::vector<std::string> probe_run = {cli, "synth", "--swatch", swatch.string(), "--backend", "cpu", "--progress",
                                          "none", "--stats", probe.string(), "-o", (work / "probe.ply").string()};
    probe_run.insert(probe_run.end(), domain.begin(), domain.end());
    meshquilt::perf::run_child(probe_run);
    const long probe_faces = nlohmann::json::parse(std::ifstream(probe))["faces"].get<long>();
    const double growth = std::sqrt(scale * sc.paper_faces / std::max(1L, probe_faces));
    if (sc.base.empty()) {
      std::snprintf(size, sizeof size, "%.2fx%.2f", growth, growth);
      domain = {"--plane", size};
    } else {
      std::snprintf(size, sizeof size, "%.4f", probe_scale / growth);
      domain = {"--base", base.string(), "--scale", size};
    }
    const std::string label = sc.paper_row + (sc.base.empty() ? " (" : " (--scale ") + size + ")";

    for (const std::string& backend : backends) {
      std::vector<Run> results;
      for (int r = 0; r < runs; ++r) {
        const auto stats = work / "stats.json";
        Run run;
        std::vector<std::string> synth = {cli, "synth", "--swatch", swatch.string(), "--backend", backend, "--progress",
                                          "none", "--stats", stats.string(), "-o", (work / "out.ply").string()};
        synth.insert(synth.end(), domain.begin(), domain.end());
        const int code = meshquilt::perf::run_child(synth, "/dev/null", &run.peak_kib);
        if (code != 0) {
          std::fprintf(stderr, "table1_runner: %s on %s failed (exit %d)\n", sc.key.c_str(), backend.c_str(), code);
          return 1;
        }
        const auto j = nlohmann::json::parse(std::ifstream(stats));
        run.seconds = j["seconds"].get<double>();
        run.faces = j["faces"].get<long>();
        for (const auto& [stage, s] : j["stages"].items()) run.stages[stage] = s.get<double>();
        results.push_back(run);
      }
      std::vector<double> seconds, peaks;
      for (const Run& r : results) {
        seconds.push_back(r.seconds);
        peaks.push_back(static_cast<double>(r.peak_kib));
      }
      const double t = median(seconds);
      std::vector<std::pair<double, std::string>> shares;
      double stage_total = 0.0;
      for (const auto& [stage, s] : results.front().stages) stage_total += s;
      for (const auto& [stage, s] : results.front().stages) shares.emplace_back(s, stage);
      std::sort(shares.rbegin(), shares.rend());
      std::string main_stages;
      for (size_t k = 0; k < std::min<size_t>(3, shares.size()); ++k) {
        char part[64];
        std::snprintf(part, sizeof part, "%s%s %.0f%%", k ? ", " : "", shares[k].second.c_str(),
                      100.0 * shares[k].first / std::max(1e-9, stage_total));
        main_stages += part;
      }
      std::printf("| %s | %s | %ld | %.1f | %.0f | %.3f | %.0f | %.0f | %s |\n", label.c_str(),
                  backend.c_str(), results.front().faces, t, sc.paper_seconds, t / sc.paper_seconds,
                  results.front().faces / t, median(peaks) / 1024.0, main_stages.c_str());
      std::fflush(stdout);
    }
  }
  std::filesystem::remove_all(work);
  return 0;
}
