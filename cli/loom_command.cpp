// `meshquilt loom --design D --exemplar A [--exemplar B ...] -o OUT`: weaves a design at yarn
// level from woven exemplars (paper 004): each crossing copies an exemplar block chosen for the
// right yarn on top, agreeing neighbours and continuing yarns; each yarn one closed tube.
#include <algorithm>
#include <chrono>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "atomic_file.h"
#include "commands.h"
#include "core/atomic_write.h"
#include "core/error.h"
#include "jobs/loom_job.h"
#include "mesh/mesh_io.h"
#include "progress.h"
#include "render/png_encoding.h"

namespace meshquilt::cli {
namespace {

struct LoomArgs {
  std::string design, output, stats, picture, method = "structured", progress = "auto";
  std::string weaves, warp_colors, weft_colors, base;
  double scale = 0.8;
  std::vector<std::string> exemplars;
  uint64_t seed = 1;
  int stations = 8, sides = 8;
  bool assignment_only = false, periodic = false;
};

void run_loom_command(const LoomArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  LoomRequest request;
  request.method = parse_assignment_method(args.method);
  request.seed = args.seed;
  request.stations = args.stations;
  request.sides = args.sides;
  request.assignment_only = args.assignment_only;
  request.periodic = args.periodic;
  if (!args.assignment_only) check_mesh_output(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);
  if (!args.picture.empty()) check_writable(args.picture);
  request.design = read_colour_image(args.design);
  request.design_name = args.design;
  if (!args.weaves.empty()) request.weaves = parse_colour_weaves(args.weaves);
  if (!args.warp_colors.empty()) request.warp_types = read_colour_image(args.warp_colors);
  if (!args.weft_colors.empty()) request.weft_types = read_colour_image(args.weft_colors);
  for (const std::string& file : args.exemplars) {
    request.exemplars.push_back(read_mesh(file));
    request.exemplar_names.push_back(file);
  }
  std::string extension = std::filesystem::path(args.output).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char ch) { return std::tolower(ch); });
  if (!args.base.empty()) {
    request.base = read_mesh(args.base);
    request.base_name = args.base;
    request.scale = args.scale;
  } else if (!args.assignment_only && extension == ".ply") {
    request.ply_output = args.output;  // streamed
  }
  check_loom_request(request);
  ProgressReporter progress(parse_progress_mode(args.progress), "loom");
  LoomOutcome outcome = run_loom(request, [&](double share) { progress.update(share, 1.0); });
  if (args.assignment_only) {
    // One line a row: "u x y" for each crossing, exemplar and its warp and weft.
    std::string text = std::to_string(outcome.assignment.rows) + " " + std::to_string(outcome.assignment.columns) + "\n";
    for (int r = 0; r < outcome.assignment.rows; ++r) {
      for (int c = 0; c < outcome.assignment.columns; ++c) {
        const LoomBlock& b = outcome.assignment.at(r, c);
        text += (c ? " " : "") + std::to_string(b.exemplar) + " " + std::to_string(b.x) + " " + std::to_string(b.y);
      }
      text += "\n";
    }
    write_text_atomic(args.output, text);
  } else if (request.ply_output.empty()) {
    write_mesh(outcome.fabric.mesh, args.output);
  }
  if (!args.picture.empty())
    write_file_atomic(args.picture,
                      encode_png(assignment_picture(
                          outcome.assignment, static_cast<int>(request.exemplars.size()),
                          std::max(1, 512 / std::max(outcome.assignment.rows, outcome.assignment.columns)))));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = {{"design_file", args.design}, {"output", args.output}};
  summary.update(outcome.stats);
  summary["seconds"] = seconds;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  progress.finish(summary.dump());
  const nlohmann::json& a = outcome.stats["loom"]["assignment"];
  std::printf("wrote %s: %d x %d crossings, %.1f%% correct, %.1f%% consistent, %.1f%% continuous, in %.2f s\n",
              args.output.c_str(), outcome.design.rows, outcome.design.columns, 100.0 * a["correct"].get<double>(),
              100.0 * a["consistent"].get<double>(), 100.0 * a["continuous"].get<double>(), seconds);
}

}  // namespace

void add_loom_command(CLI::App& app) {
  auto args = std::make_shared<LoomArgs>();
  CLI::App* cmd = app.add_subcommand(
      "loom", "Weave a design at yarn level from woven exemplars (structure-aware, Zhao et al. 2012)");
  cmd->add_option("--design", args->design,
                  "the weave design: an image (PNG, PBM, PGM, PPM), a pixel a crossing, dark where the warp "
                  "(column) lies over the weft (row)")
      ->required();
  cmd->add_option("--weaves", args->weaves,
                  "read the design's colours as weaves: RRGGBB=plain,RRGGBB=twill:2/2,RRGGBB=satin:4/1,RRGGBB=FILE.pbm");
  cmd->add_option("--warp-colors", args->warp_colors,
                  "an image whose pixel (c, 0) colours warp c (a row of yarn types; repeats)");
  cmd->add_option("--weft-colors", args->weft_colors,
                  "an image whose pixel (0, r) colours weft r (a column of yarn types; repeats)");
  cmd->add_option("--exemplar", args->exemplars, "a woven swatch mesh (repeat for more)")->required();
  cmd->add_option("-o,--output", args->output, "the fabric mesh, or with --assignment-only a text file")->required();
  cmd->add_option("--method", args->method, "naive, greedy or structured")->capture_default_str();
  cmd->add_option("--seed", args->seed, "seed of the choices among equals and the shifts")->capture_default_str();
  cmd->add_option("--stations", args->stations, "samples along a yarn per crossing (even)")->capture_default_str();
  cmd->add_option("--sides", args->sides, "vertices around each yarn")->capture_default_str();
  cmd->add_option("--base", args->base,
                  "drape the fabric over this base, a disc (one piece, one boundary), laid out in one chart");
  cmd->add_option("--scale", args->scale, "with --base: the fabric's longer side over the base's diagonal")
      ->capture_default_str();
  cmd->add_flag("--periodic", args->periodic,
                "the design is one repeat: its edges wrap round, so the fabric is a swatch for synth over a base");
  cmd->add_flag("--assignment-only", args->assignment_only,
                "write the assignment (rows columns, then per crossing: exemplar warp weft) and no geometry");
  cmd->add_option("--picture", args->picture, "a PNG of which exemplar each crossing copies (a hue each)");
  cmd->add_option("--stats", args->stats, "write the assignment's scores and the crossing grid as JSON");
  cmd->add_option("--progress", args->progress, "auto, bar, json or none")->capture_default_str();
  cmd->callback([args] { run_loom_command(*args); });
}

}  // namespace meshquilt::cli
