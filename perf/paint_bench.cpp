// Time per vertex of paint (Turk 2001 as decision 0036 builds it): paints a base from an image
// sample N times and prints the median seconds, the vertices coloured and the microseconds per
// vertex and the mean vertices scored per dispatch, as a Markdown table row, on the back end
// asked for (the CPU twin by default).
//
//   paint_bench BASE IMAGE [--scale S] [--field F.json] [--runs N] [--backend cpu|vulkan]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "device.h"
#include "mesh/base_mesh.h"
#include "mesh/measures.h"
#include "mesh/mesh_io.h"
#include "paint/colour_image.h"
#include "paint/surface_paint.h"
#include "surface/guidance_field.h"

int main(int argc, char** argv) {
  using namespace meshquilt;
  if (argc < 3) {
    std::fprintf(stderr, "usage: paint_bench BASE IMAGE [--scale S] [--field F.json] [--runs N] [--backend cpu|vulkan]\n");
    return 2;
  }
  double scale = 0.25;
  int runs = 3;
  std::string field, backend = "cpu";
  for (int i = 3; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scale")) scale = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--runs")) runs = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--field")) field = argv[i + 1];
    if (!std::strcmp(argv[i], "--backend")) backend = argv[i + 1];
  }
  const TriMesh base = prepare_base(read_mesh(argv[1]), argv[1]);
  const ColourImage sample = read_colour_image(argv[2]);
  const std::vector<FieldConstraint> constraints = field.empty() ? std::vector<FieldConstraint>{} : read_field_file(field, base);
  const std::unique_ptr<engine::Device> device = engine::open_device(engine::parse_backend_choice(backend));
  PaintOptions options;
  options.pixels_per_unit = sample.width / (scale * glm::length(bounding_box(base.positions).extent()));
  std::vector<double> seconds;
  size_t vertices = 0, visits = 0, batches = 0;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const PaintResult painted = paint_surface(base, sample, constraints, options, *device);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    vertices = painted.mesh.num_vertices();
    visits = painted.visits;
    batches = painted.batches;
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  std::printf("| base | sample | device | vertices | visits per batch | median s (of %d) | us per vertex |\n"
              "| --- | --- | --- | --- | --- | --- | --- |\n",
              runs);
  std::printf("| %s | %s (%d x %d) | %s | %zu | %.1f | %.2f | %.1f |\n", argv[1], argv[2], sample.width, sample.height,
              device->name().c_str(), vertices, static_cast<double>(visits) / static_cast<double>(std::max<size_t>(1, batches)),
              median, 1e6 * median / static_cast<double>(vertices));
  return 0;
}
