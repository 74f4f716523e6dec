// L2 stretch of a base's shell map (Section 3.2 of the mesh quilting paper) against the number of
// line-search sweeps: where the minimization converges, and what it costs. Prints a Markdown
// table of the normalized stretch and the seconds of the search, per shell height.
//
//   stretch_bench BASE [--height H]... [--sweeps N]... [--cone RADIANS]   (heights in base units)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "device.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "shell/shell_embedding.h"
#include "shell/stretch_metric.h"

int main(int argc, char** argv) {
  using namespace meshquilt;
  if (argc < 2) {
    std::fprintf(stderr, "usage: stretch_bench BASE [--height H]... [--sweeps N]... [--cone RADIANS]\n");
    return 2;
  }
  std::vector<double> heights;
  std::vector<int> sweeps;
  AtlasOptions atlas_options;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--cone")) atlas_options.max_normal_angle = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--height")) heights.push_back(std::atof(argv[i + 1]));
    if (!std::strcmp(argv[i], "--sweeps")) sweeps.push_back(std::atoi(argv[i + 1]));
  }
  if (heights.empty()) heights = {0.0054};
  if (sweeps.empty()) sweeps = {0, 20, 80, 320};
  const TriMesh base = prepare_base(read_mesh(argv[1]), argv[1]);
  const BaseSurface surface(base);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  const TextureAtlas atlas = build_texture_atlas(surface, atlas_options);
  std::printf(
      "%s: %d charts\n\n| shell height | sweeps | L2 stretch | excess removed | search (s) |\n"
      "|---|---|---|---|---|\n",
      argv[1], atlas.charts);
  for (const double height : heights) {
    const Shell shell = build_shell(surface, height);
    const double initial = measure_stretch(ShellMap(surface, atlas, shell, atlas.uv)).l2;
    for (const int n : sweeps) {
      StretchOptions options;
      options.sweeps = n;
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<glm::dvec2> top = minimize_stretch(*device, surface, atlas, shell, options);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double l2 = measure_stretch(ShellMap(surface, atlas, shell, top)).l2;
      std::printf("| %.4g | %d | %.4f | %.1f%% | %.2f |\n", height, n, l2,
                  100.0 * (initial - l2) / (initial - 1.0), seconds);
    }
  }
  return 0;
}
