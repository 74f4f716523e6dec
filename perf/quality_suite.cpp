// The planar quality suite of issue 8: every swatch kind at `--preset small`, quilted over
// `--plane 4x4` with several seeds, measured by `meshquilt inspect --plane --swatch S --json` and
// synth's `--stats`, printed as a Markdown table with the rows that miss the quality bar marked.
//
//   quality_suite [--seeds 1,2,3] [--kinds chainmail,plain,...] [--plane 4x4] [--work DIR]
//
// Columns: coverage (inspect's plane coverage with the swatch, on cells as large as the swatch's
// largest gap, and that cell size), the same
// coverage on cells sized from the swatch (the smallest whole fraction of its longer side at
// which the swatch covers itself at four grid phases), both over the plane asked for (synth's
// `plane_rect`, so elements hanging past its edges neither help nor hurt), closed share
// (closed / all output elements), intersecting share (an upper bound: 2 x intersecting face pairs,
// between and within elements, over faces), dropped share (dropped / (kept + dropped) elements),
// holes, the longest output element in swatch lengths (its longer x-y side over the swatch's),
// stitched pairs and synth's seconds. Bar: coverage >= 0.98, closed >= 0.98, intersecting
// <= 0.1%, dropped <= 1%; open sheets (height field) have no closed bar.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "inspect/coverage.h"
#include "mesh/mesh_io.h"
#include <unistd.h>

#include "run_child.h"
#include "split_list.h"

namespace {

namespace fs = std::filesystem;

struct Kind {
  std::string key;          // command-line name and table row
  std::string swatch_args;  // `meshquilt swatch` arguments besides --preset small, --seed, -o
  bool random;              // the swatch itself depends on the seed
  bool closed_by_design;    // an open sheet has no closed bar
};

const std::vector<Kind> kKinds = {
    {"chainmail", "chainmail", false, true},
    {"plain", "weave --pattern plain", false, true},
    {"twill", "weave --pattern twill:2/3", false, true},
    {"satin", "weave --pattern satin:4/1", false, true},
    {"wire", "wire", false, true},
    {"fruit", "fruit", true, true},
    {"nuts", "nuts", true, true},
    {"heightfield-tiles", "heightfield --tiles 4", false, true},
    {"heightfield-open", "heightfield --open", false, false},
};

// Longer x-y side of each element's bounding box (elements by the mesh's per-face ids).
std::vector<double> element_lengths(const meshquilt::TriMesh& m) {
  std::map<int32_t, std::pair<meshquilt::Vec3, meshquilt::Vec3>> boxes;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const int32_t e = m.elements.empty() ? 0 : m.elements[f];
    auto it = boxes.try_emplace(e, meshquilt::Vec3(INFINITY), meshquilt::Vec3(-INFINITY)).first;
    for (int32_t v : m.triangles[f]) {
      it->second.first = glm::min(it->second.first, m.positions[v]);
      it->second.second = glm::max(it->second.second, m.positions[v]);
    }
  }
  std::vector<double> lengths;
  for (const auto& [e, box] : boxes) {
    const meshquilt::Vec3 d = box.second - box.first;
    lengths.push_back(std::max(d.x, d.y));
  }
  return lengths;
}

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> seeds = {"1", "2", "3"};
  std::vector<std::string> kinds;
  for (const Kind& k : kKinds) kinds.push_back(k.key);
  std::string plane = "4x4";
  fs::path work = fs::temp_directory_path() / ("meshquilt_quality_" + std::to_string(getpid()));
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--seeds") seeds = meshquilt::perf::split(value, ',');
    else if (flag == "--kinds") kinds = meshquilt::perf::split(value, ',');
    else if (flag == "--plane") plane = value;
    else if (flag == "--work") work = value;
    else {
      std::fprintf(stderr, "quality_suite: unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  const std::string cli = MESHQUILT_CLI;
  fs::create_directories(work);

  std::printf("| swatch | seed | faces | elements | coverage (cell) | swatch-cell coverage (cell) | closed | intersecting | dropped | holes | longest (swatch lengths) | stitched pairs | s | misses |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  int misses = 0;
  for (const Kind& kind : kKinds) {
    if (std::find(kinds.begin(), kinds.end(), kind.key) == kinds.end()) continue;
    for (const std::string& seed : seeds) {
      const std::string name = kind.key + "-" + seed;
      const fs::path swatch = work / (name + "-swatch.ply"), out = work / (name + ".ply");
      const fs::path stats = work / (name + ".json"), report = work / (name + "-inspect.json");
      std::vector<std::string> make = {cli, "swatch"};
      for (const auto& a : meshquilt::perf::split(kind.swatch_args, ' ')) make.push_back(a);
      make.insert(make.end(), {"--preset", "small", "--seed", seed, "-o", swatch.string()});
      if (meshquilt::perf::run_child(make) != 0) {
        std::fprintf(stderr, "quality_suite: making the %s swatch failed\n", name.c_str());
        return 1;
      }
      const int code = meshquilt::perf::run_child({cli, "synth", "--swatch", swatch.string(), "--plane", plane, "--seed", seed, "--backend",
                              "cpu", "--progress", "none", "--stats", stats.string(), "-o", out.string()});
      if (code != 0) {
        std::printf("| %s | %s | synth failed (exit %d) | | | | | | | | | | | yes |\n", kind.key.c_str(), seed.c_str(), code);
        ++misses;
        continue;
      }
      // Both coverages are of the plane asked for (synth's plane_rect): elements hanging past its
      // edges by differing lengths neither help nor hurt.
      const auto s = nlohmann::json::parse(std::ifstream(stats));
      const std::vector<double> rect = s.at("plane_rect").get<std::vector<double>>();
      char region[256];
      std::snprintf(region, sizeof region, "%.17g,%.17g,%.17g,%.17g", rect[0], rect[1], rect[2], rect[3]);
      if (meshquilt::perf::run_child({cli, "inspect", out.string(), "--plane", "--region", region, "--swatch", swatch.string(), "--json"},
                                     report.string()) != 0) {
        std::fprintf(stderr, "quality_suite: inspecting %s failed\n", name.c_str());
        return 1;
      }
      const auto r = nlohmann::json::parse(std::ifstream(report));
      const double faces = r["faces"].get<double>();
      const double elements = r["elements"].get<double>();
      const double coverage = r["coverage"].get<double>();
      const double closed = elements > 0 ? r["closed_elements"].get<double>() / elements : 0.0;
      const double pairs = r["intersecting_face_pairs"].get<double>() + r["self_intersecting_face_pairs"].get<double>();
      const double intersecting = faces > 0 ? std::min(1.0, 2.0 * pairs / faces) : 0.0;
      const double dropped_count = s.value("dropped_elements", 0.0);
      const double kept = s.value("elements", elements);
      const double dropped = kept + dropped_count > 0 ? dropped_count / (kept + dropped_count) : 0.0;
      const meshquilt::TriMesh swatch_mesh = meshquilt::read_mesh(swatch);
      meshquilt::Vec3 lo(INFINITY), hi(-INFINITY);
      for (const auto& p : swatch_mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
      const double swatch_length = std::max(hi.x - lo.x, hi.y - lo.y);
      const meshquilt::TriMesh output = meshquilt::read_mesh(out);
      const std::vector<double> lengths = element_lengths(output);
      const double cell = meshquilt::self_covering_cell(swatch_mesh, swatch_length);
      meshquilt::PlaneCoverageOptions plane_asked;
      plane_asked.region = {glm::dvec2(rect[0], rect[1]), glm::dvec2(rect[2], rect[3])};
      const double fine_coverage = meshquilt::plane_coverage(output, cell, plane_asked).coverage;
      const double longest = lengths.empty() ? 0.0 : *std::max_element(lengths.begin(), lengths.end()) / swatch_length;

      std::vector<std::string> missed;
      if (coverage < 0.98) missed.push_back("coverage");
      if (fine_coverage < 0.98) missed.push_back("swatch-cell coverage");
      if (kind.closed_by_design && closed < 0.98) missed.push_back("closed");
      if (intersecting > 0.001) missed.push_back("intersecting");
      if (dropped > 0.01) missed.push_back("dropped");
      std::string miss_text;
      for (const auto& m : missed) miss_text += (miss_text.empty() ? "" : ", ") + m;
      misses += !missed.empty();
      std::printf("| %s | %s | %.0f | %.0f | %s (%s) | %s (%s) | %s | %s%% | %s%% | %d | %s | %d | %.0f | %s |\n", kind.key.c_str(),
                  seed.c_str(), faces, elements, fixed(coverage, 3).c_str(), fixed(r["coverage_cell_size"].get<double>(), 2).c_str(),
                  fixed(fine_coverage, 3).c_str(), fixed(cell, 2).c_str(),
                  kind.closed_by_design ? fixed(closed, 3).c_str() : "open", fixed(100.0 * intersecting, 2).c_str(),
                  fixed(100.0 * dropped, 1).c_str(), s.value("holes", 0), fixed(longest, 2).c_str(),
                  s.value("stitched_pairs", 0), s.value("seconds", 0.0), miss_text.empty() ? "-" : miss_text.c_str());
      std::fflush(stdout);
    }
  }
  std::fprintf(stderr, "quality_suite: %d row(s) miss the bar; files in %s\n", misses, work.string().c_str());
  return 0;
}
