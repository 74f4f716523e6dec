#include "synth_options.h"

#include "resource_limits.h"

namespace meshquilt::cli {

void add_synth_options(CLI::App* cmd, SynthArgs& args) {
  cmd->add_option("--swatch", args.swatch, "swatch mesh (OBJ, PLY, OFF, STL); default: a built-in chain mail");
  cmd->add_option("--plane", args.plane, "output size WxH in swatch extents")->capture_default_str();
  cmd->add_option("--seed", args.seed, "seed of every random choice")->capture_default_str();
  cmd->add_option("--backend", args.backend, "auto|vulkan|cpu: where matching costs are computed")->capture_default_str();
  cmd->add_option("--stats", args.stats, "write statistics (faces, elements, seconds per stage) as JSON");
  cmd->add_option("--progress", args.progress, "auto|json|none")->capture_default_str();
  cmd->add_option("--cells", args.cells, "grid cells along the swatch's shorter side")->capture_default_str();
  cmd->add_option("--max-patches", args.max_patches, "stop after this many patches (0: fill the plane)");
  cmd->add_flag("!--no-cleanup", args.cleanup, "keep elements that could not be made whole");
  cmd->add_option("--fill-margin", args.fill_margin,
                  "place a repeating pattern's elements straight at its periods, over a base farther than this many "
                  "periods from a cone or border (0: every element patch by patch)")
      ->capture_default_str();
  cmd->add_option("--base", args.base, "base mesh to cover (OBJ, PLY, OFF, STL) instead of a plane");
  cmd->add_option("--scale", args.scale, "with --base: swatch's longer side / base's bounding-box diagonal")
      ->capture_default_str();
  cmd->add_option("--field", args.field, "with --base: guidance field file (JSON directions at vertices or points)");
  cmd->add_flag("!--per-patch-charts", args.shared_layout,
                "with --base: flatten each patch alone instead of as a window of one field-aligned layout of the base");
  cmd->add_option("--symmetry", args.symmetry,
                  "with --base: n of the layout's direction field, 1, 2 or 4 (0: the swatch's rotational symmetry)")
      ->capture_default_str();
  cmd->add_option("--size-hold", args.size_hold,
                  "with --base: how strongly the layout holds elements to one size against keeping their shape "
                  "(0.1: conformal, round rings whose size follows the base's curvature; 3-10: even sizes, "
                  "stretched rings)")
      ->capture_default_str();
  cmd->add_option("--cone-spread", args.cone_spread,
                  "with --base and no --field, over a closed genus-0 base or a disc: cones are added to the layout "
                  "until its scale spreads at most this much (p90 / p10 by area; 1: as little as they can)")
      ->capture_default_str();
  cmd->add_option("--shell-height", args.shell_height,
                  "with --base: layer height in base units (default: the swatch's thickness at --scale)");
  cmd->add_option("--write-field", args.write_field, "with --base: write the field used as OBJ line segments");
  cmd->add_option("--embed", args.embed, "with --base: shell (stretch-minimized shell map) or normal (displacement)")
      ->capture_default_str();
  cmd->add_flag("!--no-distortion-min", args.distortion_min, "with --embed shell: keep the original shell map");
  cmd->add_option("--write-texture", args.write_texture,
                  "with --base: write the result in texture space, for `meshquilt embed` over an edited base");
  cmd->add_flag("--provenance", args.provenance,
                "write each vertex's swatch vertex as the PLY vertex property `origin` (glTF `_ORIGIN`)");
  cmd->add_option("--preview", args.preview, "write a PNG preview of the result (oblique, elements coloured)");
  add_max_memory_option(cmd);
  cmd->add_option("-o,--output", args.output, "output mesh (.ply with element ids, .obj with groups, .off, .stl, .glb)")
      ->capture_default_str();
}

std::vector<std::string> synth_input_files(const SynthArgs& args) {
  std::vector<std::string> files;
  if (!args.swatch.empty()) files.push_back(args.swatch);
  if (!args.base.empty()) files.push_back(args.base);
  if (!args.field.empty()) files.push_back(args.field);
  return files;
}

std::vector<std::string> synth_output_files(const SynthArgs& args) {
  std::vector<std::string> files{args.output};
  if (!args.stats.empty()) files.push_back(args.stats);
  if (!args.write_field.empty()) files.push_back(args.write_field);
  if (!args.preview.empty()) files.push_back(args.preview);
  if (!args.write_texture.empty()) files.push_back(args.write_texture);
  return files;
}

}  // namespace meshquilt::cli
