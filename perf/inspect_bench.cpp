// Times the full inspect report (topology, intersections, swatch KS, plane coverage) on a
// 1,000,000-face mesh of 2,000 rings of 500 faces: half the rows are chains of linked rings,
// half are loose rings. Prints each run, the median, and the median time per stage.
//
//   inspect_bench [--runs N] [--base] [--write PREFIX]
//     --base    also times base coverage and heights over a plane under the rings
//     --write   also writes PREFIX_mesh.ply and PREFIX_swatch.ply, to time `meshquilt inspect`
//               end to end (file reading included)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "inspect/inspect_report.h"
#include "mesh/mesh_io.h"

namespace {

using meshquilt::Tri;
using meshquilt::TriMesh;
using meshquilt::Vec3;

void add_ring(TriMesh& m, const Vec3& center, const Vec3& a, const Vec3& b, double R, double r, int nu, int nv) {
  const auto base = static_cast<int32_t>(m.positions.size());
  const Vec3 n = glm::cross(a, b);
  for (int i = 0; i < nu; ++i) {
    const double u = 2.0 * std::numbers::pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2.0 * std::numbers::pi * j / nv;
      m.positions.push_back(center + (R + r * std::cos(v)) * (std::cos(u) * a + std::sin(u) * b) + r * std::sin(v) * n);
    }
  }
  auto id = [&](int i, int j) { return base + ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
}

// rows x per_row rings of 25 x 10 quads (500 faces); even rows are linked chains.
TriMesh ring_field(int rows, int per_row) {
  TriMesh m;
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  for (int row = 0; row < rows; ++row) {
    const bool chain = row % 2 == 0;
    for (int i = 0; i < per_row; ++i) {
      const Vec3 c((chain ? 1.5 : 2.6) * i, 2.6 * row, 0.0);
      add_ring(m, c, x, (chain && i % 2) ? z : y, 1.0, 0.2, 25, 10);
    }
  }
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  bool with_base = false;
  std::string write_prefix;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--base")) with_base = true;
    else if (!std::strcmp(argv[i], "--write") && i + 1 < argc) write_prefix = argv[++i];
  }
  const TriMesh mesh = ring_field(40, 50);
  const TriMesh swatch = ring_field(2, 4);
  TriMesh base;
  base.positions = {{-3, -3, -0.5}, {120, -3, -0.5}, {120, 105, -0.5}, {-3, 105, -0.5}};
  base.triangles = {{0, 1, 2}, {0, 2, 3}};
  std::printf("mesh: %zu faces, %zu vertices; swatch: %zu faces\n", mesh.num_faces(), mesh.num_vertices(), swatch.num_faces());
  if (!write_prefix.empty()) {
    meshquilt::write_mesh(mesh, write_prefix + "_mesh.ply");
    meshquilt::write_mesh(swatch, write_prefix + "_swatch.ply");
    std::printf("wrote %s_mesh.ply and %s_swatch.ply\n", write_prefix.c_str(), write_prefix.c_str());
  }

  auto bench = [&](const char* name, const meshquilt::InspectOptions& options, const TriMesh* b) {
    std::vector<double> totals;
    std::map<std::string, std::vector<double>> stages;
    std::vector<std::string> order;
    for (int run = 0; run < runs; ++run) {
      const auto t0 = std::chrono::steady_clock::now();
      const meshquilt::InspectReport report = meshquilt::inspect_mesh(mesh, options, &swatch, b);
      totals.push_back(seconds_since(t0));
      for (const auto& [stage, s] : report.timings) {
        if (!stages.count(stage)) order.push_back(stage);
        stages[stage].push_back(s);
      }
      std::printf("%s run %d: %.2f s (%d elements, %d closed, %lld intersecting pairs)\n", name, run + 1, totals.back(),
                  report.elements, report.closed_elements, static_cast<long long>(report.intersecting_face_pairs));
    }
    std::printf("%s median: %.2f s over %d runs\n", name, median(totals), runs);
    for (const std::string& stage : order) std::printf("  %-16s %.2f s\n", stage.c_str(), median(stages[stage]));
  };

  meshquilt::InspectOptions plane;
  plane.plane = true;
  bench("full report (--swatch --plane)", plane, nullptr);
  if (with_base) {
    meshquilt::InspectOptions over_base;
    over_base.shell_height = 0.05;
    bench("full report (--swatch --base)", over_base, &base);
  }
  return 0;
}
