#include "jobs/synth_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/memory_budget.h"
#include "jobs/repairs_json.h"
#include "mesh/base_mesh.h"
#include "mesh/measures.h"
#include "mesh/swatch_frame.h"
#include "quilt/planar_quilting.h"
#include "shell/shell_embedding.h"
#include "spatial/near_face_grid_cache.h"
#include "swatch/default_swatch.h"

namespace meshquilt {
namespace {

// What either driver reports.
nlohmann::json quilt_stats(const QuiltStats& stats) {
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
      {"filled_elements", stats.filled_elements},
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

void add_curved_stats(const SynthRequest& request, const SurfaceQuiltStats& stats, const ShellReport& shell,
                      nlohmann::json& out) {
  out["embed"] = request.embed;
  out["intersecting_face_pairs"] = stats.intersecting_face_pairs;
  out["synthesis_map_elements"] = stats.synthesis_map_elements;
  const CopySizes& sizes = stats.element_size;
  out["element_size"] = {{"copies", sizes.copies}, {"p10", sizes.p10}, {"median", sizes.median}, {"p90", sizes.p90}};
  out["size_correction"] = stats.size_correction;
  if (request.embed == "shell") {
    out["stretch_l2_initial"] = shell.stretch_initial;
    out["stretch_l2_final"] = shell.stretch_final;
    out["shell_tets"] = shell.tets;
    out["shell_charts"] = shell.charts;
    out["shell_reduced_vertices"] = shell.reduced_vertices;
    out["shell_invalid_prisms"] = shell.invalid_prisms;
    out["shell_offset_crossings"] = shell.offset_intersections;
    out["stages"]["atlas"] = shell.seconds_atlas;
    out["stages"]["shell_build"] = shell.seconds_shell;
    out["stages"]["stretch"] = shell.seconds_stretch;
  }
  out["base"] = request.base_name;
  out["base_faces"] = stats.base_faces;
  out["scale"] = request.scale;
  out["shrunk_patches"] = stats.shrunk_patches;
  out["layout_windows"] = stats.layout_windows;
  out["field_symmetry"] = stats.field_symmetry;
  out["cones"] = stats.cones;
  out["cone_points"] = nlohmann::json::array();
  for (const Vec3& p : stats.cone_points) out["cone_points"].push_back({p.x, p.y, p.z});
  out["cone_indices"] = stats.cone_indices;
  if (stats.layout_scale_spread > 0.0) out["layout_scale_spread"] = stats.layout_scale_spread;
  out["outside_vertices"] = stats.outside_vertices;
  out["shell_height"] = stats.shell_height;
  out["shell_height_share"] = stats.diagonal > 0.0 ? stats.shell_height / stats.diagonal : 0.0;
  out["hole_area"] = stats.hole_area;
  out["covered_area"] = stats.covered_area;
  out["field"] = request.field_name.empty() ? "default" : request.field_name;
}

}  // namespace

std::string synth_swatch_name(const SynthRequest& request) {
  return request.swatch_name.empty() ? "built-in chain mail" : request.swatch_name;
}

void check_synth_request(const SynthRequest& r) {
  auto fail = [](const std::string& text) { throw InputError(text, ErrorKind::invalid_option); };
  const bool curved = r.base.has_value();
  if (curved == r.plane.has_value()) fail("give a plane ({plane}) or a base ({base}), not both");
  if (r.plane && !(r.plane->x > 0.0 && r.plane->y > 0.0 && r.plane->x <= 1000.0 && r.plane->y <= 1000.0)) {
    char text[128];
    std::snprintf(text, sizeof text, "{plane}: sizes must lie in (0, 1000], got '%gx%g'", r.plane->x, r.plane->y);
    fail(text);
  }
  if (r.symmetry != 0 && r.symmetry != 1 && r.symmetry != 2 && r.symmetry != 4)
    fail("{symmetry}: expected 0, 1, 2 or 4, got " + std::to_string(r.symmetry));
  if (curved && !(r.scale > 0.0 && r.scale <= 10.0))
    fail("{scale}: expected a value in (0, 10], got " + std::to_string(r.scale));
  if (curved && !(r.shell_height >= 0.0 && std::isfinite(r.shell_height)))
    fail("{shell_height}: expected a non-negative length");
  if (!curved && !r.field.empty()) fail("{field} needs {base}");
  if (r.embed != "shell" && r.embed != "normal") fail("{embed}: expected shell or normal, got '" + r.embed + "'");
  if (r.cells < 4 || r.cells > 256) fail("{cells}: expected 4..256, got " + std::to_string(r.cells));
  if (!(r.cone_spread >= 1.0 && r.cone_spread <= 1000.0))
    fail("{cone_spread}: expected a number in [1, 1000], got " + std::to_string(r.cone_spread));
  if (!(r.size_hold > 0.0 && r.size_hold <= 1000.0))
    fail("{size_hold}: expected a number in (0, 1000], got " + std::to_string(r.size_hold));
  if (!(r.fill_margin >= 0.0) || !std::isfinite(r.fill_margin))
    fail("{fill_margin}: expected a number >= 0, got " + std::to_string(r.fill_margin));
}

double estimate_synth_bytes(const TriMesh& swatch, double width, double height) {
  const double faces = static_cast<double>(swatch.num_faces()) * width * height;
  return 400.0 * faces + 64.0 * 1024 * 1024;
}

SynthInputs prepare_synth_inputs(const SynthRequest& request) {
  SynthInputs inputs;
  // Oriented here as well as in the drivers, so a degenerate swatch is reported by its name.
  inputs.swatch = orient_swatch(request.swatch ? *request.swatch : default_swatch(), synth_swatch_name(request),
                                &inputs.swatch_repairs);
  if (request.base) {
    inputs.base = prepare_base(*request.base, request.base_name, &inputs.base_repairs);
  } else if (request.plane) {
    const double width = request.plane->x, height = request.plane->y;
    char what[96];
    std::snprintf(what, sizeof what, "{plane} %gx%g: the output (about %.3g faces)", width, height,
                  static_cast<double>(inputs.swatch.num_faces()) * width * height);
    check_memory_budget(estimate_synth_bytes(inputs.swatch, width, height), what);
  }
  return inputs;
}

SynthOutcome run_synth(const SynthRequest& request, const SynthInputs& inputs, engine::Device& device,
                       const SynthHooks& hooks) {
  const auto start = std::chrono::steady_clock::now();
  QuiltOptions common;
  common.seed = request.seed;
  common.cells_across_swatch = request.cells;
  common.max_patches = request.max_patches;
  common.cleanup = request.cleanup;
  common.fill_margin = request.fill_margin;
  common.matching.grid_folder = request.grid_folder;
  common.cancel = hooks.cancel;
  common.progress = hooks.progress;
  SynthOutcome outcome;
  if (request.base) {
    SurfaceQuiltOptions options;
    static_cast<QuiltOptions&>(options) = common;
    options.scale = request.scale;
    options.shell_height = request.shell_height;
    options.shared_layout = request.shared_layout;
    options.symmetry = request.symmetry;
    options.size_hold = request.size_hold;
    options.cone_spread = request.cone_spread;
    const BaseSurface surface(inputs.base);
    const GuidanceField field = interpolate_field(surface, request.field);
    if (hooks.field_ready) hooks.field_ready(surface, field);
    ShellEmbeddingOptions shell_options;
    shell_options.minimize_stretch = request.distortion_min;
    shell_options.stretch.seed = request.seed;
    ShellReport shell_report;
    if (request.embed == "shell")
      options.embedding = [&](const BaseSurface& surface_base, double shell_height) {
        auto embedding = build_shell_embedding(device, surface_base, shell_height, shell_options, &shell_report);
        if (request.keep_texture) outcome.shell_texture = embedding->texture();
        return std::unique_ptr<SurfaceEmbedding>(std::move(embedding));
      };
    SurfaceQuiltStats stats;
    SurfaceQuilt quilt = quilt_surface(inputs.swatch, inputs.base, field, device, options, &stats);
    outcome.mesh = std::move(quilt.mesh);
    outcome.local = std::move(quilt.local);
    outcome.stats = quilt_stats(stats);
    add_curved_stats(request, stats, shell_report, outcome.stats);
  } else {
    PlanarQuiltOptions options;
    static_cast<QuiltOptions&>(options) = common;
    options.width = request.plane->x;
    options.height = request.plane->y;
    QuiltStats stats;
    outcome.mesh = quilt_plane(inputs.swatch, device, options, &stats);
    outcome.stats = quilt_stats(stats);
    outcome.stats["plane"] = {request.plane->x, request.plane->y};
    outcome.stats["plane_rect"] = {0.0, 0.0, stats.plane_extent.x, stats.plane_extent.y};
  }
  // An empty file would pass for a result: say why there is none instead.
  if (outcome.mesh.num_faces() == 0)
    throw InputError(synth_swatch_name(request) + ": nothing was quilted: " +
                         (request.base ? "no element fits " + request.base_name + " at {scale} " +
                                             std::to_string(request.scale) + " (try a smaller {scale})"
                                       : "every element was dropped (open, folded or intersecting; see swatch check)"),
                     ErrorKind::invalid_option);

  nlohmann::json& stats = outcome.stats;
  int32_t elements = 0;
  for (int32_t e : outcome.mesh.elements) elements = std::max(elements, e + 1);
  stats["swatch"] = synth_swatch_name(request);
  stats["repairs"]["swatch"] = repairs_json(inputs.swatch_repairs);
  if (request.base) stats["repairs"]["base"] = repairs_json(inputs.base_repairs);
  stats["faces"] = outcome.mesh.num_faces();
  stats["vertices"] = outcome.mesh.num_vertices();
  stats["elements"] = elements;
  stats["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats["backend"] = engine::backend_name(device.backend());
  stats["device"] = device.name();
  stats["seed"] = request.seed;
  return outcome;
}

}  // namespace meshquilt
