// matching_cost throughput, in (candidate, point) pairs per second, on each back end, at a
// typical size: a 2,048-face swatch, 2,000 output points, 64 candidates; the swatch's
// nearest-face grid with geometry matching's proportions.
// Run: matching_cost_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>
#include <glm/glm.hpp>

#include <cmath>
#include <ctime>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "device.h"
#include "core/error.h"
#include "matching_cost.h"
#include "spatial/near_face_grid.h"

namespace meshquilt {
namespace {

constexpr int kGrid = 32;          // 32 x 32 quads = 2,048 faces
constexpr float kExtent = 8.0f;    // swatch spans [0,8]^2
constexpr int kPoints = 2000;
constexpr int kCandidatesPerSide = 8;  // 64 candidates

float height(float x, float y) { return 0.3f * std::sin(2.0f * x) * std::cos(1.7f * y); }

glm::vec3 height_normal(float x, float y) {
  const float dx = 0.6f * std::cos(2.0f * x) * std::cos(1.7f * y);
  const float dy = -0.51f * std::sin(2.0f * x) * std::sin(1.7f * y);
  return glm::normalize(glm::vec3(-dx, -dy, 1.0f));
}

MatchingSwatch make_swatch() {
  MatchingSwatch swatch;
  const float h = kExtent / kGrid;
  for (int j = 0; j <= kGrid; ++j)
    for (int i = 0; i <= kGrid; ++i) swatch.positions.emplace_back(i * h, j * h, height(i * h, j * h));
  auto index = [](int i, int j) { return static_cast<std::uint32_t>(j * (kGrid + 1) + i); };
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      swatch.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      swatch.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  for (const auto& t : swatch.triangles)
    swatch.normals.push_back(glm::normalize(glm::cross(swatch.positions[t[1]] - swatch.positions[t[0]],
                                                       swatch.positions[t[2]] - swatch.positions[t[0]])));
  swatch.lambda = kGrid / kExtent;  // 1 / the grid spacing, about 1 / mean edge as the drivers set it
  return swatch;
}

NearFaceGrid make_grid(const MatchingSwatch& swatch) {
  TriMesh mesh;
  for (const glm::vec3& p : swatch.positions) mesh.positions.emplace_back(p);
  for (const auto& t : swatch.triangles)
    mesh.triangles.push_back({static_cast<int32_t>(t[0]), static_cast<int32_t>(t[1]), static_cast<int32_t>(t[2])});
  const double edge = kExtent / kGrid;
  return build_near_face_grid(mesh, 0.75 * edge, edge, 1.5 * edge, 3.0 * edge, 128);
}

struct Query {
  std::vector<glm::vec3> points, normals;
  std::vector<glm::vec2> translations;
};

// Output points on a shifted copy of the surface over a sub-patch half the swatch's size, and
// grid-unit translations for which the swatch covers the sub-patch.
Query make_query(float cell) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> coordinate(2.0f, 6.0f);
  Query query;
  for (int k = 0; k < kPoints; ++k) {
    const float x = coordinate(rng), y = coordinate(rng);
    query.points.emplace_back(x, y, height(x + 0.37f, y - 0.21f));
    query.normals.push_back(height_normal(x + 0.37f, y - 0.21f));
  }
  for (int a = 0; a < kCandidatesPerSide; ++a)
    for (int b = 0; b < kCandidatesPerSide; ++b)
      query.translations.emplace_back((a - kCandidatesPerSide / 2) * cell * 0.5f,
                                      (b - kCandidatesPerSide / 2) * cell * 0.5f);
  return query;
}

void run(benchmark::State& state, engine::Device& device) {
  const MatchingSwatch swatch = make_swatch();
  const Query query = make_query(kExtent / 16.0f);  // about 16 cells along the shorter side
  MatchingCost cost(device, swatch, make_grid(swatch));
  cost.score(query.points, query.normals, query.translations);  // compiles the pipeline lazily
  double device_seconds = 0.0;
  // Process CPU time counts every thread (TBB's and lavapipe's): throughput per CPU-second is
  // what survives a machine shared with other jobs.
  const std::clock_t cpu_start = std::clock();
  for (auto _ : state) {
    benchmark::DoNotOptimize(cost.score(query.points, query.normals, query.translations));
    device_seconds += cost.last_timing().device_seconds;
  }
  const double pairs = static_cast<double>(query.points.size() * query.translations.size());
  state.counters["pairs_per_s"] = benchmark::Counter(pairs * state.iterations(), benchmark::Counter::kIsRate);
  const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  if (cpu_seconds > 0.0) state.counters["pairs_per_cpu_s"] = pairs * state.iterations() / cpu_seconds;
  state.counters["faces"] = static_cast<double>(swatch.triangles.size());
  if (device_seconds > 0.0) state.counters["device_pairs_per_s"] = pairs * state.iterations() / device_seconds;
}

}  // namespace
}  // namespace meshquilt

int main(int argc, char** argv) {
  using namespace meshquilt;
  benchmark::Initialize(&argc, argv);
  std::vector<std::unique_ptr<engine::Device>> devices;
  devices.push_back(engine::open_device(engine::BackendChoice::cpu));
  try {
    devices.push_back(engine::open_device(engine::BackendChoice::vulkan));
  } catch (const DeviceError& error) {
    std::cerr << "skipping the Vulkan back end: " << error.what() << "\n";
  }
  for (auto& device : devices) {
    const std::string name = std::string("matching_cost/") + engine::backend_name(device->backend());
    engine::Device* raw = device.get();
    benchmark::RegisterBenchmark(name.c_str(), [raw](benchmark::State& state) { run(state, *raw); })
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    std::cerr << engine::backend_name(device->backend()) << ": " << device->name() << "\n";
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
