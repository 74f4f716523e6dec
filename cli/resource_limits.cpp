#include "resource_limits.h"

#include <cstdio>
#include <string>

#include "core/memory_budget.h"

namespace meshquilt::cli {

void add_max_memory_option(CLI::App* cmd) {
  cmd->add_option_function<std::string>(
      "--max-memory", [](const std::string& text) { set_memory_budget(parse_memory_size(text)); },
      "memory budget for the job, e.g. 8G (default: " + format_bytes(static_cast<double>(default_memory_budget())) +
          ", 3/4 of the memory this process may use)");
}

double estimate_synth_bytes(const TriMesh& swatch, double width, double height) {
  const double faces = static_cast<double>(swatch.num_faces()) * width * height;
  return 400.0 * faces + 64.0 * 1024 * 1024;
}

void check_synth_memory(const TriMesh& swatch, double width, double height) {
  const double faces = static_cast<double>(swatch.num_faces()) * width * height;
  char plane[96];
  std::snprintf(plane, sizeof(plane), "--plane %gx%g: the output (about %.3g faces)", width, height, faces);
  check_memory_budget(estimate_synth_bytes(swatch, width, height), plane);
}

}  // namespace meshquilt::cli
