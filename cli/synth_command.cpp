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
#include "device.h"
#include "core/error.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "progress.h"
#include "repair_report.h"
#include "resource_limits.h"
#include "signals.h"
#include "synth_command.h"
#include "mesh/base_mesh.h"
#include "mesh/measures.h"
#include "surface/guidance_field.h"
#include "quilt/planar_quilting.h"
#include "surface/surface_quilting.h"
#include "shell/shell_embedding.h"
#include "shell/texture_file.h"
#include "render_command.h"
#include "swatch/default_swatch.h"

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

// What either driver reports, for the stats JSON.
nlohmann::json quilt_summary(const QuiltStats& stats) {
  return {
      {"patches", stats.patches},
      {"stitched_pairs", stats.merges.stitched},
      {"bridged_pairs", stats.merges.bridged},
      {"replaced_elements", stats.merges.replaced},
      {"yielded_inputs", stats.merges.kept},
      {"rejected_inputs", stats.merges.rejected_inputs},
      {"refused_merges", stats.merges.refused_merges},
      {"undone_deformations", stats.merges.undone_deformations},
      {"refused_pinned", stats.merges.refused_pinned},
      {"lattice_copies", stats.merges.lattice_copies},
      {"on_lattice", stats.on_lattice},
      {"dropped_elements", stats.dropped_elements},
      {"dropped_open", stats.dropped_open},
      {"dropped_folded", stats.dropped_folded},
      {"cut_swatch_elements", stats.cut_swatch_elements},
      {"dropped_intersecting", stats.dropped_intersecting},
      {"joined_elements", stats.joined_elements},
      {"cells", stats.cells},
      {"cell_size", stats.cell_size},
      {"holes", stats.holes},
      {"hole_cells", stats.hole_cells},
      {"largest_hole_area", stats.largest_hole_area},
      {"stages", stats.stage_seconds},
      {"grid", to_string(stats.grid_source)},
  };
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
  if (args.symmetry != 0 && args.symmetry != 1 && args.symmetry != 2 && args.symmetry != 4)
    throw InputError("--symmetry: expected 0, 1, 2 or 4, got " + std::to_string(args.symmetry), ErrorKind::invalid_option);
  if (curved && !(args.scale > 0.0 && args.scale <= 10.0))
    throw InputError("--scale: expected a value in (0, 10], got " + std::to_string(args.scale), ErrorKind::invalid_option);
  if (curved && !(args.shell_height >= 0.0 && std::isfinite(args.shell_height)))
    throw InputError("--shell-height: expected a non-negative length", ErrorKind::invalid_option);
  if (!curved && (!args.field.empty() || !args.write_field.empty() || !args.write_texture.empty()))
    throw InputError("--field, --write-field and --write-texture need --base", ErrorKind::invalid_option);
  if (args.embed != "shell" && args.embed != "normal")
    throw InputError("--embed: expected shell or normal, got '" + args.embed + "'", ErrorKind::invalid_option);
  settings.backend = engine::parse_backend_choice(args.backend);
  settings.progress_mode = parse_progress_mode(args.progress);
  if (args.cells < 4 || args.cells > 256)
    throw InputError("--cells: expected 4..256, got " + std::to_string(args.cells), ErrorKind::invalid_option);
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

// What a quilting driver hands to the writers.
struct SynthResult {
  TriMesh mesh;
  nlohmann::json summary;
  std::vector<LocalVertex> local;  // texture-space coordinates (curved jobs)
  ShellTexture shell_texture;      // the shell map's texture (with --write-texture)
};

void add_curved_summary(const SynthArgs& args, const SurfaceQuiltStats& stats, const ShellReport& shell_report,
                        nlohmann::json& summary) {
  summary["embed"] = args.embed;
  summary["intersecting_face_pairs"] = stats.intersecting_face_pairs;
  summary["synthesis_map_elements"] = stats.synthesis_map_elements;
  if (args.embed == "shell") {
    summary["stretch_l2_initial"] = shell_report.stretch_initial;
    summary["stretch_l2_final"] = shell_report.stretch_final;
    summary["shell_tets"] = shell_report.tets;
    summary["shell_charts"] = shell_report.charts;
    summary["shell_reduced_vertices"] = shell_report.reduced_vertices;
    summary["shell_invalid_prisms"] = shell_report.invalid_prisms;
    summary["shell_offset_crossings"] = shell_report.offset_intersections;
    summary["stages"]["atlas"] = shell_report.seconds_atlas;
    summary["stages"]["shell_build"] = shell_report.seconds_shell;
    summary["stages"]["stretch"] = shell_report.seconds_stretch;
  }
  summary["base"] = args.base;
  summary["base_faces"] = stats.base_faces;
  summary["scale"] = args.scale;
  summary["shrunk_patches"] = stats.shrunk_patches;
  summary["layout_windows"] = stats.layout_windows;
  summary["field_symmetry"] = stats.field_symmetry;
  summary["cones"] = stats.cones;
  summary["outside_vertices"] = stats.outside_vertices;
  summary["shell_height"] = stats.shell_height;
  summary["shell_height_share"] = stats.diagonal > 0.0 ? stats.shell_height / stats.diagonal : 0.0;
  summary["hole_area"] = stats.hole_area;
  summary["covered_area"] = stats.covered_area;
  summary["field"] = args.field.empty() ? "default" : args.field;
}

SynthResult synth_curved(const SynthArgs& args, const TriMesh& swatch, const TriMesh& base,
                         const std::vector<FieldConstraint>& constraints, engine::Device& device,
                         const QuiltOptions& common) {
  SurfaceQuiltOptions options;
  static_cast<QuiltOptions&>(options) = common;
  options.scale = args.scale;
  options.shell_height = args.shell_height;
  options.shared_layout = args.shared_layout;
  options.symmetry = args.symmetry;
  const BaseSurface surface(base);
  const GuidanceField field = interpolate_field(surface, constraints);
  if (!args.write_field.empty()) write_field_obj(surface, field, 0.5 * mean_edge_length(base), args.write_field);
  ShellEmbeddingOptions shell_options;
  shell_options.minimize_stretch = args.distortion_min;
  shell_options.stretch.seed = args.seed;
  SynthResult result;
  ShellReport shell_report;
  if (args.embed == "shell")
    options.embedding = [&](const BaseSurface& surface_base, double shell_height) {
      auto embedding = build_shell_embedding(device, surface_base, shell_height, shell_options, &shell_report);
      if (!args.write_texture.empty()) result.shell_texture = embedding->texture();
      return std::unique_ptr<SurfaceEmbedding>(std::move(embedding));
    };
  SurfaceQuiltStats stats;
  SurfaceQuilt quilt = quilt_surface(swatch, base, field, device, options, &stats);
  result.mesh = std::move(quilt.mesh);
  result.local = std::move(quilt.local);
  result.summary = quilt_summary(stats);
  add_curved_summary(args, stats, shell_report, result.summary);
  return result;
}

SynthResult synth_planar(const TriMesh& swatch, double width, double height, engine::Device& device,
                         const QuiltOptions& common) {
  PlanarQuiltOptions options;
  static_cast<QuiltOptions&>(options) = common;
  options.width = width;
  options.height = height;
  QuiltStats stats;
  SynthResult result;
  result.mesh = quilt_plane(swatch, device, options, &stats);
  result.summary = quilt_summary(stats);
  result.summary["plane"] = {width, height};
  result.summary["plane_rect"] = {0.0, 0.0, stats.plane_extent.x, stats.plane_extent.y};
  return result;
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

void run_synth(const SynthArgs& args) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const bool curved = !args.base.empty();
  const SynthSettings settings = check_synth_args(args);
  const double width = settings.width, height = settings.height;
  const ProgressMode progress_mode = settings.progress_mode;
  const std::filesystem::path output = args.output;

  const std::string swatch_name = args.swatch.empty() ? "built-in chain mail" : args.swatch;
  // Oriented here as well as in the drivers, so a degenerate swatch is reported by file name.
  MeshRepairs swatch_repairs, base_repairs;
  const TriMesh swatch =
      orient_swatch(args.swatch.empty() ? default_swatch() : read_mesh(args.swatch), swatch_name, &swatch_repairs);
  say_repairs(swatch_name, swatch_repairs, "elements");
  TriMesh base;
  std::vector<FieldConstraint> constraints;
  if (curved) {
    base = prepare_base(read_mesh(args.base), args.base, &base_repairs);
    say_repairs(args.base, base_repairs, "parts");
    if (!args.field.empty()) constraints = read_field_file(args.field, base);
  } else {
    check_synth_memory(swatch, width, height);
  }

  std::string note;
  std::unique_ptr<engine::Device> device = engine::open_device(settings.backend, &note);
  if (!note.empty()) std::cerr << "meshquilt: " << with_options(note) << "\n";

  ProgressReporter progress(progress_mode, "synth");
  QuiltOptions common;
  common.seed = args.seed;
  common.cells_across_swatch = args.cells;
  common.max_patches = args.max_patches;
  common.cleanup = args.cleanup;
  common.matching.grid_folder = cache_folder();
  common.cancel = &interrupt_token();
  common.progress = [&](const QuiltProgress& p) {
    check_interrupted();  // stops after the current patch until the scheduler polls options.cancel
    progress.update(p.covered_area, p.total_area);
  };
  SynthResult synth = curved ? synth_curved(args, swatch, base, constraints, *device, common)
                             : synth_planar(swatch, width, height, *device, common);
  TriMesh& result = synth.mesh;
  nlohmann::json& summary = synth.summary;
  // An empty file would pass for a result: say why there is none instead.
  if (result.num_faces() == 0)
    throw InputError(swatch_name + ": nothing was quilted: " +
                         (curved ? "no element fits " + args.base + " at --scale " + std::to_string(args.scale) +
                                       " (try a smaller --scale)"
                                 : "every element was dropped (open, folded or intersecting; see swatch check)"),
                     ErrorKind::invalid_option);

  const auto write_start = Clock::now();
  check_interrupted();
  // Provenance goes into the texture file always, into the mesh only when asked.
  std::vector<int32_t> origins;
  if (!args.provenance) origins.swap(result.origins);
  write_mesh(result, output, WriteOptions{.cancel = &interrupt_token()});
  if (!args.provenance) origins.swap(result.origins);
  if (!args.write_texture.empty())
    write_texture_file(args.write_texture, make_quilt_texture(base, result, synth.local, synth.shell_texture));
  if (!args.preview.empty()) write_synth_preview(result, curved ? &base : nullptr, args.preview);
  summary["stages"]["write"] = std::chrono::duration<double>(Clock::now() - write_start).count();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

  int32_t elements = 0;
  for (int32_t e : result.elements) elements = std::max(elements, e + 1);
  summary["output"] = output.string();
  summary["swatch"] = swatch_name;
  summary["repairs"]["swatch"] = repairs_json(swatch_repairs);
  if (curved) summary["repairs"]["base"] = repairs_json(base_repairs);
  summary["faces"] = result.num_faces();
  summary["vertices"] = result.num_vertices();
  summary["elements"] = elements;
  summary["seconds"] = seconds;
  summary["backend"] = engine::backend_name(device->backend());
  summary["device"] = device->name();
  summary["seed"] = args.seed;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  progress.finish(summary.dump());
  if (const int cut = summary["cut_swatch_elements"].get<int>(); cut > 0)
    std::fprintf(stderr, "meshquilt: %s: left out %d element%s cut open by its border\n", swatch_name.c_str(), cut,
                 cut == 1 ? "" : "s");
  if (progress_mode != ProgressMode::json)
    std::printf("wrote %s: %zu faces, %d elements (%d dropped) in %.1f s on %s\n", output.string().c_str(),
                result.num_faces(), elements, summary["dropped_elements"].get<int>(), seconds, device->name().c_str());
}

void add_synth_command(CLI::App& app) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* cmd = app.add_subcommand("synth", "Grow a geometric texture over a plane or a base mesh by mesh quilting");
  add_synth_options(cmd, *args);
  cmd->callback([args] { run_synth(*args); });
}

}  // namespace meshquilt::cli
