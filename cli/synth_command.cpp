// `meshquilt synth`: grows a geometric texture over a plane (Section 2 of the paper).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "commands.h"
#include "device.h"
#include "error.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "progress.h"
#include "resource_limits.h"
#include "signals.h"
#include "quilt/planar_quilting.h"
#include "default_swatch.h"

namespace meshquilt::cli {
namespace {

struct SynthArgs {
  std::string swatch;
  std::string plane = "4x4";
  uint64_t seed = 1;
  std::string backend = "auto";
  std::string stats;
  std::string progress = "auto";
  std::string output = "quilt.ply";
  int cells = 16;
  int max_patches = 0;
  bool cleanup = true;
};

void parse_plane(const std::string& text, double* width, double* height) {
  const size_t x = text.find_first_of("xX");
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    size_t used_w = 0, used_h = 0;
    *width = std::stod(text.substr(0, x), &used_w);
    *height = std::stod(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    throw InputError("--plane: expected WxH in swatch extents (e.g. 4x4), got '" + text + "'",
                     ExitCode::invalid_option);
  }
  if (!(*width > 0.0 && *height > 0.0 && *width <= 1000.0 && *height <= 1000.0))
    throw InputError("--plane: sizes must lie in (0, 1000], got '" + text + "'", ExitCode::invalid_option);
}

void check_mesh_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".stl")
    throw IoError(ExitCode::unknown_format, file.string() + ": unknown output format (use .ply, .obj, .off or .stl)");
}

void run_synth(const SynthArgs& args) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double width = 0.0, height = 0.0;
  parse_plane(args.plane, &width, &height);
  const engine::BackendChoice backend = engine::parse_backend_choice(args.backend);
  const ProgressMode progress_mode = parse_progress_mode(args.progress);
  if (args.cells < 4 || args.cells > 256)
    throw InputError("--cells: expected 4..256, got " + std::to_string(args.cells), ExitCode::invalid_option);
  const std::filesystem::path output = args.output;
  check_mesh_extension(output);
  check_writable(output);
  if (!args.stats.empty()) check_writable(args.stats);

  const std::string swatch_name = args.swatch.empty() ? "built-in chain mail" : args.swatch;
  // Oriented here as well as in quilt_plane, so a degenerate swatch is reported by file name.
  const TriMesh swatch = orient_swatch(args.swatch.empty() ? default_swatch() : read_mesh(args.swatch), swatch_name);
  check_synth_memory(swatch, width, height);

  std::string note;
  std::unique_ptr<engine::Device> device = engine::open_device(backend, &note);
  if (!note.empty()) std::cerr << "meshquilt: " << note << "\n";

  ProgressReporter progress(progress_mode, "synth");
  PlanarQuiltOptions options;
  options.width = width;
  options.height = height;
  options.seed = args.seed;
  options.cells_across_swatch = args.cells;
  options.max_patches = args.max_patches;
  options.cleanup = args.cleanup;
  options.cancel = &interrupt_token();
  options.progress = [&](const QuiltProgress& p) {
    check_interrupted();  // stops after the current patch until the scheduler polls options.cancel
    progress.update(p.processed_cells, p.total_cells);
  };
  QuiltStats stats;
  const TriMesh result = quilt_plane(swatch, *device, options, &stats);

  const auto write_start = Clock::now();
  check_interrupted();
  write_mesh(result, output, WriteOptions{.cancel = &interrupt_token()});
  stats.stage_seconds["write"] = std::chrono::duration<double>(Clock::now() - write_start).count();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

  int32_t elements = 0;
  for (int32_t e : result.elements) elements = std::max(elements, e + 1);
  nlohmann::json summary = {
      {"output", output.string()},
      {"swatch", swatch_name},
      {"faces", result.num_faces()},
      {"vertices", result.num_vertices()},
      {"elements", elements},
      {"seconds", seconds},
      {"backend", engine::backend_name(device->backend())},
      {"device", device->name()},
      {"seed", args.seed},
      {"plane", {width, height}},
      {"patches", stats.patches},
      {"stitched_pairs", stats.merges.stitched},
      {"replaced_elements", stats.merges.replaced},
      {"yielded_inputs", stats.merges.kept},
      {"rejected_inputs", stats.merges.rejected_inputs},
      {"refused_merges", stats.merges.refused_merges},
      {"undone_deformations", stats.merges.undone_deformations},
      {"dropped_elements", stats.dropped_elements},
      {"dropped_open", stats.dropped_open},
      {"dropped_intersecting", stats.dropped_intersecting},
      {"cells", stats.cells},
      {"cell_size", stats.cell_size},
      {"holes", stats.holes},
      {"hole_cells", stats.hole_cells},
      {"largest_hole_area", stats.largest_hole_area},
      {"stages", stats.stage_seconds},
  };
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  progress.finish(summary.dump());
  if (progress_mode != ProgressMode::json)
    std::printf("wrote %s: %zu faces, %d elements (%d dropped) in %.1f s on %s\n", output.string().c_str(),
                result.num_faces(), elements, stats.dropped_elements, seconds, device->name().c_str());
}

}  // namespace

void add_synth_command(CLI::App& app) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* cmd = app.add_subcommand("synth", "Grow a geometric texture over a plane by mesh quilting");
  cmd->add_option("--swatch", args->swatch, "swatch mesh (OBJ, PLY, OFF, STL); default: a built-in chain mail");
  cmd->add_option("--plane", args->plane, "output size WxH in swatch extents")->capture_default_str();
  cmd->add_option("--seed", args->seed, "seed of every random choice")->capture_default_str();
  cmd->add_option("--backend", args->backend, "auto|vulkan|cpu: where matching costs are computed")->capture_default_str();
  cmd->add_option("--stats", args->stats, "write statistics (faces, elements, seconds per stage) as JSON");
  cmd->add_option("--progress", args->progress, "auto|json|none")->capture_default_str();
  cmd->add_option("--cells", args->cells, "grid cells along the swatch's shorter side")->capture_default_str();
  cmd->add_option("--max-patches", args->max_patches, "stop after this many patches (0: fill the plane)");
  cmd->add_flag("!--no-cleanup", args->cleanup, "keep elements that could not be made whole");
  add_max_memory_option(cmd);
  cmd->add_option("-o,--output", args->output, "output mesh (.ply with element ids, .obj with groups, .off, .stl)")
      ->capture_default_str();
  cmd->callback([args] { run_synth(*args); });
}

}  // namespace meshquilt::cli
