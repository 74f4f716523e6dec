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
#include "loom_options.h"
#include "progress.h"
#include "render/png_encoding.h"

namespace meshquilt::cli {
namespace {


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
  add_loom_options(cmd, *args);
  cmd->callback([args] { run_loom_command(*args); });
}

}  // namespace meshquilt::cli
