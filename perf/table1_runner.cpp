// Reproduces rows of Table 1 of the mesh quilting paper with our closest swatches: for each
// scenario and back end, runs `meshquilt synth` several times in a child process and prints our
// median seconds, the paper's, their ratio, faces per second, peak memory and the share of time
// per stage, as a Markdown table. Planar rows size the plane, curved rows the --scale over the
// base, for about the paper's output faces (or, where a row says so, its element count); rows
// not in Table 1 may fix the plane instead. Each row also times the floor: a plain tiling of the same swatch to the same number of faces
// (vertices copied and offset, binary PLY written), and gives the ratio to it. "ours" is a first
// job over the swatch (its nearest-face grid built, and written to an empty cache folder);
// "grid read" a later one, which reads the grid from there.
//
//   table1_runner [--runs N] [--backends cpu,vulkan]
//                 [--scenarios small-chain,wire,apple,twill,bunny-weave,bunny-link] [--scale F] [--shared DIR]
//
// --scale multiplies the output faces of sized rows (0.1 for a quick look); --shared is where data/meshes/
// holds the curved rows' bases (default: ../shared beside the source tree).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/common.hpp>

#include "mesh/mesh_io.h"
#include "run_child.h"
#include "split_list.h"

#include <nlohmann/json.hpp>

namespace {

struct Scenario {
  std::string key;           // command-line name
  std::string paper_row;     // Table 1 row
  double paper_seconds;      // Table 1 time (0: not in Table 1)
  long paper_faces;          // Table 1 output faces
  long paper_elements;       // Table 1 output elements; when set, the output is sized by them
  std::string swatch_args;   // `meshquilt swatch` arguments of our closest swatch
  std::string base;          // base mesh under <shared>/data/meshes; empty: a plane
  std::string plane;         // a fixed --plane, not sized from the paper's output
};

const std::vector<Scenario> kScenarios = {
    // The small chain mail over a 4x4 plane: the job whose ratio to the plain tiling is watched.
    {"small-chain", "Plane + small chain mail (not in Table 1)", 0.0, 0, 0, "chainmail --preset small", "", "4x4"},
    // 27 long wires in the paper: our sparse crimped wire mesh.
    {"wire", "Plane + Wire", 3 * 60.0, 74792, 0, "wire", "", ""},
    // 86 apples of 3,733 faces each in the paper; ours have 5,120 (icosahedra subdivided 4 times),
    // so the plane is sized for 86 of them.
    {"apple", "Plane + Apple", 3 * 60.0, 321046, 86, "fruit --columns 4 --rows 4 --subdivisions 4", "", ""},
    {"twill", "Plane + Twill (not in Table 1)", 0.0, 361268, 0, "weave --pattern twill:2/3", "", ""},
    {"bunny-weave", "Bunny + Weave", 86 * 60.0, 700815, 0, "weave", "bunny.off", ""},
    {"bunny-link", "Bunny + Link", 80 * 60.0, 940622, 0, "chainmail --rows 8 --columns 6", "bunny.off", ""},
};

// The floor: copies of the swatch side by side on a grid, each one's vertices copied and offset,
// up to `faces` faces, written as binary PLY; seconds.
double plain_tiling_seconds(const meshquilt::TriMesh& swatch, long faces, const std::filesystem::path& out) {
  const auto start = std::chrono::steady_clock::now();
  meshquilt::Vec3 low(INFINITY), high(-INFINITY);
  for (const auto& p : swatch.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const long copies = (faces + static_cast<long>(swatch.num_faces()) - 1) / static_cast<long>(swatch.num_faces());
  const long side = static_cast<long>(std::ceil(std::sqrt(static_cast<double>(copies))));
  meshquilt::TriMesh tiled;
  tiled.positions.reserve(swatch.num_vertices() * copies);
  tiled.triangles.reserve(swatch.num_faces() * copies);
  for (long c = 0; c < copies; ++c) {
    const meshquilt::Vec3 offset((c % side) * (high.x - low.x), (c / side) * (high.y - low.y), 0.0);
    const auto base = static_cast<int32_t>(tiled.positions.size());
    for (const auto& p : swatch.positions) tiled.positions.push_back(p + offset);
    for (const auto& t : swatch.triangles) tiled.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  meshquilt::write_mesh(tiled, out);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Run {
  double seconds = 0.0;
  long faces = 0;
  long elements = 0;
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
  std::vector<std::string> scenarios = {"small-chain", "wire", "apple", "twill", "bunny-weave", "bunny-link"};
  std::filesystem::path shared = std::filesystem::path(MESHQUILT_SOURCE_DIR) / ".." / "shared";
  if (argc % 2 == 0) {  // an option without its value, or --help
    std::fprintf(stderr,
                 "usage: table1_runner [--runs N] [--backends cpu,vulkan] [--scenarios small-chain,wire,apple,twill,"
                 "bunny-weave,bunny-link] [--scale F] [--shared DIR]\n");
    return 2;
  }
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
  ::setenv("MESHQUILT_CACHE", "off", 1);  // the swatches and probes; the timed runs choose below

  std::printf("| scenario | backend | faces out | elements | ours (s, median of %d) | grid read (s) | paper (s) | ours / paper | "
              "faces/s | peak MiB | main stages | plain tiling (s) | ours / tiling |\n", runs);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
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
    if (!sc.plane.empty()) {
      std::snprintf(size, sizeof size, "%s", sc.plane.c_str());
      domain = {"--plane", sc.plane};
    } else {
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
      const auto probed = nlohmann::json::parse(std::ifstream(probe));
      const double growth =
          sc.paper_elements > 0
              ? std::sqrt(scale * sc.paper_elements / std::max(1.0, probed["elements"].get<double>()))
              : std::sqrt(scale * sc.paper_faces / std::max(1.0, probed["faces"].get<double>()));
      if (sc.base.empty()) {
        std::snprintf(size, sizeof size, "%.2fx%.2f", growth, growth);
        domain = {"--plane", size};
      } else {
        std::snprintf(size, sizeof size, "%.4f", probe_scale / growth);
        domain = {"--base", base.string(), "--scale", size};
      }
    }
    const std::string label = sc.paper_row + (sc.base.empty() ? " (" : " (--scale ") + size + ")";

    for (const std::string& backend : backends) {
      // A job as a user's first over the swatch (its nearest-face grid built and written to an
      // empty cache folder), then as every later one (the grid read from there).
      const auto grids = work / ("grids-" + backend);
      const auto run_synth = [&](Run& run) {
        const auto stats = work / "stats.json";
        std::vector<std::string> synth = {cli, "synth", "--swatch", swatch.string(), "--backend", backend, "--progress",
                                          "none", "--stats", stats.string(), "-o", (work / "out.ply").string()};
        synth.insert(synth.end(), domain.begin(), domain.end());
        const int code = meshquilt::perf::run_child(synth, "/dev/null", &run.peak_kib);
        if (code != 0) {
          std::fprintf(stderr, "table1_runner: %s on %s failed (exit %d)\n", sc.key.c_str(), backend.c_str(), code);
          return false;
        }
        const auto j = nlohmann::json::parse(std::ifstream(stats));
        run.seconds = j["seconds"].get<double>();
        run.faces = j["faces"].get<long>();
        run.elements = j["elements"].get<long>();
        for (const auto& [stage, s] : j["stages"].items()) run.stages[stage] = s.get<double>();
        return true;
      };
      std::vector<Run> results;
      std::vector<double> read_seconds;
      ::setenv("MESHQUILT_CACHE", grids.c_str(), 1);
      for (int r = 0; r < runs; ++r) {
        std::filesystem::remove_all(grids);
        Run run;
        if (!run_synth(run)) return 1;
        results.push_back(run);
      }
      for (int r = 0; r < runs; ++r) {
        Run run;
        if (!run_synth(run)) return 1;
        read_seconds.push_back(run.seconds);
      }
      ::setenv("MESHQUILT_CACHE", "off", 1);
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
      const meshquilt::TriMesh tile = meshquilt::read_mesh(swatch);
      std::vector<double> floors;
      for (int r = 0; r < runs; ++r) floors.push_back(plain_tiling_seconds(tile, results.front().faces, work / "tiled.ply"));
      const double floor = median(floors);
      const std::string paper = sc.paper_seconds > 0.0 ? std::to_string(static_cast<long>(sc.paper_seconds)) : "-";
      char ratio[32] = "-";
      if (sc.paper_seconds > 0.0) std::snprintf(ratio, sizeof ratio, "%.3f", t / sc.paper_seconds);
      std::printf("| %s | %s | %ld | %ld | %.1f | %.1f | %s | %s | %.0f | %.0f | %s | %.3f | %.0f |\n", label.c_str(),
                  backend.c_str(), results.front().faces, results.front().elements, t, median(read_seconds),
                  paper.c_str(), ratio, results.front().faces / t, median(peaks) / 1024.0, main_stages.c_str(), floor,
                  t / floor);
      std::fflush(stdout);
    }
  }
  std::filesystem::remove_all(work);
  return 0;
}
