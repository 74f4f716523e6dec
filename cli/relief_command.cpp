// `meshquilt relief --base B --image HEIGHTS --height H -o OUT`: a relief synthesized over a base
// from a height image (white high), as paint synthesizes colour, then the base displaced.
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>


#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "image_synthesis_inputs.h"
#include "mesh/mesh_io.h"
#include "paint/surface_relief.h"

namespace meshquilt::cli {
namespace {

struct ReliefArgs {
  std::string base, image, output, field, stats;
  double scale = 0.25;
  double pixels_per_unit = 0.0;
  ReliefOptions options;
};

void run_relief(ReliefArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const ImageSynthesisInputs in = read_image_synthesis_inputs(args.base, args.image, args.field, args.scale,
                                                               args.pixels_per_unit, args.output, args.stats);
  args.options.paint.pixels_per_unit = in.pixels_per_unit;
  const ReliefResult relief = relief_surface(in.base, in.sample, in.constraints, args.options);
  write_mesh(relief.mesh, args.output);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double highest = 0.0;
  for (double h : relief.heights) highest = std::max(highest, h);
  const nlohmann::json summary = {{"base", args.base},
                                  {"image", args.image},
                                  {"output", args.output},
                                  {"pixels_per_unit", args.options.paint.pixels_per_unit},
                                  {"levels", relief.levels},
                                  {"vertices", relief.mesh.num_vertices()},
                                  {"faces", relief.mesh.num_faces()},
                                  {"height", args.options.height},
                                  {"highest", highest},
                                  {"clamped_vertices", relief.clamped},
                                  {"seconds", seconds}};
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  std::printf("wrote %s: %zu vertices raised by up to %g (%d clamped to their room) in %.1f s\n", args.output.c_str(),
              relief.mesh.num_vertices(), highest, relief.clamped, seconds);
}

}  // namespace

void add_relief_command(CLI::App& app) {
  auto args = std::make_shared<ReliefArgs>();
  CLI::App* cmd = app.add_subcommand(
      "relief", "Raise a relief over a base from a height image (white high), synthesized as paint does");
  cmd->add_option("--base", args->base, "base mesh (.obj .ply .off .stl)")->required();
  cmd->add_option("--image", args->image, "heights: PGM/PBM/PPM or PNG, white high")->required();
  cmd->add_option("--height", args->options.height, "the displacement of white, in base units")->required();
  cmd->add_option("-o,--output", args->output, "the base refined and displaced (.ply .glb .obj .off .stl)")->required();
  cmd->add_option("--scale", args->scale, "the image's width over the base's bounding-box diagonal")
      ->capture_default_str();
  cmd->add_option("--pixels-per-unit", args->pixels_per_unit, "image pixels per base unit (instead of --scale)");
  cmd->add_option("--field", args->field, "guidance field file, as synth's --field");
  cmd->add_option("--clearance", args->options.clearance,
                  "share of the room along a normal (to the surface met, or the radius of a hollow) a height may take")
      ->capture_default_str();
  cmd->add_option("--window", args->options.paint.window, "neighbourhood width in pixels, odd, 3..21")
      ->capture_default_str();
  cmd->add_option("--seed", args->options.paint.seed, "seed of every random choice")->capture_default_str();
  cmd->add_option("--stats", args->stats, "write figures as JSON");
  cmd->callback([args] { run_relief(*args); });
}

}  // namespace meshquilt::cli
