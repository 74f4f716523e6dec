// `meshquilt relief --base B --image HEIGHTS --height H -o OUT`: a relief synthesized over a base
// from a height image (white high), as paint synthesizes colour, then the base displaced. With
// `--from MODEL` instead of an image, the sample is the detail of another model (Lai et al.
// 2005): the model minus its smoothed self, over a region of it, flattened into a height image.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <glm/geometric.hpp>


#include "repair_report.h"
#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "image_synthesis_inputs.h"
#include "jobs/image_jobs.h"
#include "mesh/mesh_io.h"
#include "mesh/base_mesh.h"
#include "mesh/measures.h"
#include "paint/detail_extraction.h"
#include "paint/surface_relief.h"
#include "paint_options.h"
#include "progress.h"
#include "signals.h"

namespace meshquilt::cli {
namespace {

// The model's detail over its region as the sample, sized as an image sample is (--scale or
// --pixels-per-unit), its heights scaled as its widths are unless --height is given.
nlohmann::json sample_from_model(ReliefArgs& args, ImageSynthesisInputs& in, bool height_given, bool ppu_given) {
  MeshRepairs repairs;
  const TriMesh model = prepare_base(read_mesh(args.model), args.model, &repairs);
  say_repairs(args.model, repairs, "parts");
  if (!args.region.empty() && args.region.size() != 4)
    throw InputError("--region: expected X,Y,Z,RADIUS in model units", ErrorKind::invalid_option);
  std::optional<DetailRegion> region;
  if (!args.region.empty()) region = DetailRegion{Vec3(args.region[0], args.region[1], args.region[2]), args.region[3]};
  ModelSample sample;
  try {
    sample = model_sample(model, args.smoothing, region, args.pixels, in.base, args.scale,
                          ppu_given ? args.pixels_per_unit : 0.0);
  } catch (const InputError& e) {
    throw InputError(args.model + ": " + e.text(), e.kind());  // the one model file the error is about
  }
  in.sample = sample.image;
  in.pixels_per_unit = sample.pixels_per_unit;
  if (!height_given) args.options.height = sample.height;
  nlohmann::json from = sample.from;
  from["model"] = args.model;
  return from;
}

// The sample's luma, as relief reads it, as a 16-bit plain PGM.
std::string grey_pgm(const ColourImage& image) {
  std::string text = "P2\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n65535\n";
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const glm::dvec3& c = image.at(x, y);
      const double grey = std::clamp(luma(c), 0.0, 1.0);
      text += std::to_string(std::lround(65535.0 * grey)) + (x + 1 < image.width ? " " : "\n");
    }
  }
  return text;
}

void run_relief(ReliefArgs& args, bool height_given) {
  const auto start = std::chrono::steady_clock::now();
  if (!args.write_sample.empty()) check_writable(args.write_sample);
  if (!args.write_field.empty()) check_writable(args.write_field);
  ImageSynthesisInputs in = read_image_synthesis_inputs(args.base, args.image, args.field, args.scale,
                                                         args.pixels_per_unit, args.sample_width, args.output, args.stats);
  nlohmann::json from;
  if (!args.model.empty()) from = sample_from_model(args, in, height_given, args.pixels_per_unit > 0.0);
  args.options.paint.pixels_per_unit = in.pixels_per_unit;
  if (!args.write_sample.empty()) write_text_atomic(args.write_sample, grey_pgm(in.sample));
  const std::unique_ptr<engine::Device> device = open_synthesis_device(args.backend);
  const ProgressMode progress_mode = parse_progress_mode(args.progress);
  ProgressReporter progress(progress_mode, "relief");
  args.options.paint.progress = paint_progress(progress);
  args.options.paint.cancel = &interrupt_token();
  const ReliefResult relief = relief_surface(in.base, in.sample, in.constraints, args.options, *device);
  write_mesh(relief.mesh, args.output, WriteOptions{.cancel = &interrupt_token()});
  if (relief.crossing_left > 0)
    std::fprintf(stderr, "meshquilt: %s passes through itself, and the relief crosses there too (%zu face pair%s)\n",
                 args.base.c_str(), relief.crossing_left, relief.crossing_left == 1 ? "" : "s");
  if (!args.write_field.empty()) write_field_lines(args.write_field, relief.directions);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = relief_stats(relief, args.options, *device);
  summary["base"] = args.base;
  summary["image"] = args.image;
  summary["output"] = args.output;
  summary["seconds"] = seconds;
  const double highest = summary["highest"].get<double>();
  if (!from.is_null()) summary["from"] = from;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  progress.finish(summary.dump());
  if (progress_mode == ProgressMode::json) return;
  std::printf("wrote %s: %zu vertices raised by up to %g (%d clamped to their room) in %.1f s\n", args.output.c_str(),
              relief.mesh.num_vertices(), highest, relief.clamped, seconds);
}

}  // namespace

void add_relief_command(CLI::App& app) {
  auto args = std::make_shared<ReliefArgs>();
  CLI::App* cmd = app.add_subcommand(
      "relief", "Raise a relief over a base from a height image (white high), synthesized as paint does");
  add_relief_options(cmd, *args);
  CLI::Option* height = cmd->get_option("--height");
  cmd->callback([args, height] { run_relief(*args, height->count() > 0); });
}

}  // namespace meshquilt::cli
