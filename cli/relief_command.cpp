// `meshquilt relief --base B --image HEIGHTS --height H -o OUT`: a relief synthesized over a base
// from a height image (white high), as paint synthesizes colour, then the base displaced.
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "paint/colour_image.h"
#include "paint/surface_relief.h"
#include "surface/guidance_field.h"

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
  if (!(args.scale > 0.0 && args.scale <= 10.0))
    throw InputError("--scale: expected a value in (0, 10], got " + std::to_string(args.scale), ErrorKind::invalid_option);
  check_mesh_output(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);
  const TriMesh base = prepare_base(read_mesh(args.base), args.base);
  const ColourImage sample = read_colour_image(args.image);
  std::vector<FieldConstraint> constraints;
  if (!args.field.empty()) constraints = read_field_file(args.field, base);
  Vec3 lo = base.positions.front(), hi = lo;
  for (const Vec3& p : base.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  args.options.paint.pixels_per_unit =
      args.pixels_per_unit > 0.0 ? args.pixels_per_unit : sample.width / (args.scale * glm::length(hi - lo));
  const ReliefResult relief = relief_surface(base, sample, constraints, args.options);
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
