#include "paint_options.h"

#include "core/error.h"

namespace meshquilt::cli {
namespace {

std::vector<std::string> given(std::initializer_list<const std::string*> files) {
  std::vector<std::string> out;
  for (const std::string* f : files)
    if (!f->empty()) out.push_back(*f);
  return out;
}

}  // namespace

void add_paint_options(CLI::App* cmd, PaintArgs& args) {
  cmd->add_option("--base", args.base, "base mesh (.obj .ply .off .stl)")->required();
  cmd->add_option("--image", args.image, "the sample: PNG, or PPM/PGM/PBM")->required();
  cmd->add_option("-o,--output", args.output, "the base refined, with vertex colours (.ply .glb .obj .off .stl)")
      ->required();
  cmd->add_option("--scale", args.scale, "the sample's width over the base's bounding-box diagonal")
      ->capture_default_str();
  cmd->add_option("--pixels-per-unit", args.pixels_per_unit, "sample pixels per base unit (instead of --scale)");
  cmd->add_option("--sample-width", args.sample_width,
                  "shrink the image to this many pixels across first (a box filter, aspect kept): a large photo "
                  "at a size the base can hold");
  cmd->add_option("--field", args.field, "guidance field file, as synth's --field");
  cmd->add_option("--window", args.options.window, "neighbourhood width in pixels, odd, 3..21")->capture_default_str();
  cmd->add_option("--passes", args.options.passes, "the sweep, then passes over whole neighbourhoods")
      ->capture_default_str();
  cmd->add_option("--coherence", args.options.coherence,
                  "weight against a sample position few neighbours propose, 0..100")
      ->capture_default_str();
  cmd->add_option("--seed", args.options.seed, "seed of every random choice")->capture_default_str();
  cmd->add_option("--backend", args.backend, "auto|vulkan|cpu: where neighbourhoods are scored")->capture_default_str();
  cmd->add_option("--progress", args.progress, "auto|json|none")->capture_default_str();
  cmd->add_option("--atlas", args.atlas,
                  "bake the colours into an N x N texture over the base's charts: writes the base with UVs (.glb only)");
  cmd->add_option("--stats", args.stats, "write figures as JSON");
  cmd->add_option("--write-field", args.write_field,
                  "write the field each output vertex was painted along, one 'x y z' line per vertex");
}

void add_relief_options(CLI::App* cmd, ReliefArgs& args) {
  cmd->add_option("--base", args.base, "base mesh (.obj .ply .off .stl)")->required();
  CLI::Option* image = cmd->add_option("--image", args.image, "heights: PGM/PBM/PPM or PNG, white high");
  cmd->add_option("--from", args.model, "a model whose detail (it minus its smoothed self) is the sample")
      ->excludes(image);
  CLI::Option* height = cmd->add_option(
      "--height", args.options.height,
      "the displacement of white, in base units (with --from: the detail's own, scaled as its width is)");
  cmd->add_option("--region", args.region, "with --from: X,Y,Z,RADIUS, the ball of the model sampled "
                                           "(default: where its detail varies most, radius 0.1 of its diagonal)")
      ->delimiter(',')
      ->expected(4);
  cmd->add_option("--smoothing", args.smoothing,
                  "with --from: the smoothing length, model units (default: 0.01 of its diagonal)");
  cmd->add_option("--pixels", args.pixels, "with --from: the sample's pixels a side")->capture_default_str();
  cmd->add_option("-o,--output", args.output, "the base refined and displaced (.ply .glb .obj .off .stl)")->required();
  cmd->add_option("--scale", args.scale, "the image's width over the base's bounding-box diagonal")
      ->capture_default_str();
  cmd->add_option("--pixels-per-unit", args.pixels_per_unit, "image pixels per base unit (instead of --scale)");
  cmd->add_option("--sample-width", args.sample_width,
                  "with --image: shrink it to this many pixels across first (a box filter, aspect kept)");
  cmd->add_option("--field", args.field, "guidance field file, as synth's --field");
  cmd->add_option("--clearance", args.options.clearance,
                  "share of the room along a normal (to the surface met, or the radius of a hollow) a height may take")
      ->capture_default_str();
  cmd->add_option("--window", args.options.paint.window, "neighbourhood width in pixels, odd, 3..21")
      ->capture_default_str();
  cmd->add_option("--seed", args.options.paint.seed, "seed of every random choice")->capture_default_str();
  cmd->add_option("--backend", args.backend, "auto|vulkan|cpu: where neighbourhoods are scored")->capture_default_str();
  cmd->add_option("--progress", args.progress, "auto|json|none")->capture_default_str();
  cmd->add_option("--stats", args.stats, "write figures as JSON");
  cmd->add_option("--write-sample", args.write_sample, "write the height sample used (grey, 16-bit PGM)");
  cmd->add_option("--write-field", args.write_field,
                  "write the field each output vertex was synthesized along, one 'x y z' line per vertex");
  // Checked at parse, so that a batch manifest's job is refused before any job runs.
  cmd->parse_complete_callback([&args, height] {
    if (args.image.empty() == args.model.empty())
      throw InputError("relief: expected one of --image and --from", ErrorKind::invalid_option);
    if (!args.image.empty() && height->count() == 0)
      throw InputError("--height: required with --image", ErrorKind::invalid_option);
  });
}

std::vector<std::string> paint_input_files(const PaintArgs& args) { return given({&args.base, &args.image, &args.field}); }

std::vector<std::string> paint_output_files(const PaintArgs& args) {
  return given({&args.output, &args.stats, &args.write_field});
}

std::vector<std::string> relief_input_files(const ReliefArgs& args) {
  return given({&args.base, &args.image, &args.model, &args.field});
}

std::vector<std::string> relief_output_files(const ReliefArgs& args) {
  return given({&args.output, &args.stats, &args.write_sample, &args.write_field});
}

}  // namespace meshquilt::cli
