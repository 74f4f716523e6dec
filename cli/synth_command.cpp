// `meshquilt synth`: grows a geometric texture over a plane (Section 2 of the paper) or a base
// mesh (Section 3).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "cache_folder.h"
#include "commands.h"
#include "core/error.h"
#include "device.h"
#include "exit_codes.h"
#include "jobs/synth_job.h"
#include "mesh/measures.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "progress.h"
#include "render_command.h"
#include "repair_report.h"
#include "shell/texture_file.h"
#include "signals.h"
#include "surface/guidance_field.h"
#include "synth_command.h"

namespace meshquilt::cli {
namespace {

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
                     ErrorKind::invalid_option);
  }
  if (!(*width > 0.0 && *height > 0.0 && *width <= 1000.0 && *height <= 1000.0))
    throw InputError("--plane: sizes must lie in (0, 1000], got '" + text + "'", ErrorKind::invalid_option);
}

// The options parsed, every option and output path checked before any work starts.
struct SynthSettings {
  double width = 0.0, height = 0.0;  // the plane's size (planar jobs)
  engine::BackendChoice backend;
  ProgressMode progress_mode;
};

SynthSettings check_synth_args(const SynthArgs& args) {
  SynthSettings settings;
  const bool curved = !args.base.empty();
  if (!curved) parse_plane(args.plane, &settings.width, &settings.height);
  if (!curved && (!args.field.empty() || !args.write_field.empty() || !args.write_texture.empty()))
    throw InputError("--field, --write-field and --write-texture need --base", ErrorKind::invalid_option);
  settings.backend = engine::parse_backend_choice(args.backend);
  settings.progress_mode = parse_progress_mode(args.progress);
  check_mesh_output(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);
  if (!args.write_field.empty()) check_writable(args.write_field);
  if (!args.write_texture.empty()) check_writable(args.write_texture);
  if (!args.preview.empty()) {
    if (std::filesystem::path(args.preview).extension() != ".png")
      throw IoError(ErrorKind::unknown_format, args.preview + ": previews are PNG files (use .png)");
    check_writable(args.preview);
  }
  return settings;
}

// The preview: over a base, the base under its texture in plain grey (an element id after the
// output's).
void write_synth_preview(const TriMesh& result, const TriMesh* base, const std::string& file) {
  RenderOptions preview_options;
  preview_options.width = 900;
  preview_options.height = 700;
  preview_options.mode = RenderMode::elements;
  if (!base) {
    write_preview(result, file, preview_options);
    return;
  }
  TriMesh shown = join_elements({result, *base});
  int32_t base_id = 0;
  for (int32_t e : result.elements) base_id = std::max(base_id, e + 1);
  for (size_t f = result.num_faces(); f < shown.num_faces(); ++f) shown.elements[f] = base_id;
  for (size_t f = 0; f < result.num_faces(); ++f) shown.elements[f] = result.elements[f];
  preview_options.plain_element = base_id;
  write_preview(shown, file, preview_options);
}

}  // namespace

// The request of a command line; its meshes are read once its values are checked.
SynthRequest synth_request(const SynthArgs& args, const SynthSettings& settings) {
  SynthRequest request;
  request.swatch_name = args.swatch;
  if (!args.base.empty()) {
    request.base.emplace();
    request.base_name = args.base;
  } else {
    request.plane = glm::dvec2(settings.width, settings.height);
  }
  request.scale = args.scale;
  request.seed = args.seed;
  request.cells = args.cells;
  request.max_patches = args.max_patches;
  request.cleanup = args.cleanup;
  request.fill_margin = args.fill_margin;
  request.symmetry = args.symmetry;
  request.size_hold = args.size_hold;
  request.cone_spread = args.cone_spread;
  request.shell_height = args.shell_height;
  request.embed = args.embed;
  request.shared_layout = args.shared_layout;
  request.distortion_min = args.distortion_min;
  request.field_name = args.field;
  request.keep_texture = !args.write_texture.empty();
  request.grid_folder = cache_folder();
  return request;
}

void run_synth(const SynthArgs& args) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const bool curved = !args.base.empty();
  const SynthSettings settings = check_synth_args(args);
  const ProgressMode progress_mode = settings.progress_mode;
  const std::filesystem::path output = args.output;

  SynthRequest request = synth_request(args, settings);
  check_synth_request(request);
  if (!args.swatch.empty()) request.swatch = read_mesh(args.swatch);
  if (curved) request.base = read_mesh(args.base);
  const SynthInputs inputs = prepare_synth_inputs(request);
  const std::string swatch_name = synth_swatch_name(request);
  say_repairs(swatch_name, inputs.swatch_repairs, "elements");
  if (curved) {
    say_repairs(args.base, inputs.base_repairs, "parts");
    if (!args.field.empty()) request.field = read_field_file(args.field, inputs.base);
  }

  std::string note;
  std::unique_ptr<engine::Device> device = engine::open_device(settings.backend, &note);
  if (!note.empty()) std::cerr << "meshquilt: " << with_options(note) << "\n";

  ProgressReporter progress(progress_mode, "synth");
  SynthHooks hooks;
  hooks.cancel = &interrupt_token();
  hooks.progress = [&](const QuiltProgress& p) {
    check_interrupted();  // stops after the current patch until the scheduler polls the token
    progress.update(p.covered_area, p.total_area);
  };
  if (!args.write_field.empty())
    hooks.field_ready = [&](const BaseSurface& surface, const GuidanceField& field) {
      write_field_obj(surface, field, 0.5 * mean_edge_length(inputs.base), args.write_field);
    };
  SynthOutcome synth = run_synth(request, inputs, *device, hooks);
  TriMesh& result = synth.mesh;
  nlohmann::json& summary = synth.stats;

  const auto write_start = Clock::now();
  check_interrupted();
  // Provenance goes into the texture file always, into the mesh only when asked.
  std::vector<int32_t> origins;
  if (!args.provenance) origins.swap(result.origins);
  write_mesh(result, output, WriteOptions{.cancel = &interrupt_token()});
  if (!args.provenance) origins.swap(result.origins);
  if (!args.write_texture.empty())
    write_texture_file(args.write_texture, make_quilt_texture(inputs.base, result, synth.local, synth.shell_texture));
  if (!args.preview.empty()) write_synth_preview(result, curved ? &inputs.base : nullptr, args.preview);
  summary["stages"]["write"] = std::chrono::duration<double>(Clock::now() - write_start).count();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  summary["output"] = output.string();
  summary["seconds"] = seconds;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  progress.finish(summary.dump());
  if (const int cut = summary["cut_swatch_elements"].get<int>(); cut > 0)
    std::fprintf(stderr, "meshquilt: %s: left out %d element%s cut open by its border\n", swatch_name.c_str(), cut,
                 cut == 1 ? "" : "s");
  if (progress_mode != ProgressMode::json)
    std::printf("wrote %s: %zu faces, %d elements (%d dropped) in %.1f s on %s\n", output.string().c_str(),
                result.num_faces(), summary["elements"].get<int>(), summary["dropped_elements"].get<int>(), seconds,
                device->name().c_str());
}

void add_synth_command(CLI::App& app) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* cmd = app.add_subcommand("synth", "Grow a geometric texture over a plane or a base mesh by mesh quilting");
  add_synth_options(cmd, *args);
  cmd->callback([args] { run_synth(*args); });
}

}  // namespace meshquilt::cli
