// `meshquilt paint --base B --image SAMPLE -o OUT`: colour synthesized over a base from an image
// sample (Turk 2001), oriented by the same guidance field as synth.
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>


#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "image_synthesis_inputs.h"
#include "jobs/image_jobs.h"
#include "mesh/mesh_io.h"
#include "paint/colour_atlas.h"
#include "paint/surface_paint.h"
#include "paint_options.h"
#include "progress.h"
#include "render/png_encoding.h"
#include "signals.h"

namespace meshquilt::cli {
namespace {

void run_paint(PaintArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  std::string extension = std::filesystem::path(args.output).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (args.atlas != 0 && extension != ".glb")
    throw InputError("--atlas: writes a textured .glb, not " + args.output, ErrorKind::invalid_option);
  if (args.atlas != 0 && (args.atlas < 16 || args.atlas > 16384))
    throw InputError("--atlas: expected 16..16384 texels a side, got " + std::to_string(args.atlas), ErrorKind::invalid_option);
  if (!args.write_field.empty()) check_writable(args.write_field);
  const ImageSynthesisInputs in = read_image_synthesis_inputs(args.base, args.image, args.field, args.scale,
                                                               args.pixels_per_unit, args.sample_width, args.output, args.stats);
  args.options.pixels_per_unit = in.pixels_per_unit;
  const std::unique_ptr<engine::Device> device = open_synthesis_device(args.backend);
  const ProgressMode progress_mode = parse_progress_mode(args.progress);
  ProgressReporter progress(progress_mode, "paint");
  args.options.progress = paint_progress(progress);
  args.options.cancel = &interrupt_token();
  const PaintResult painted = paint_surface(in.base, in.sample, in.constraints, args.options, *device);
  nlohmann::json baked;
  if (args.atlas != 0) {
    const ColourAtlas atlas = bake_colour_atlas(in.base, painted.mesh, painted.levels, args.atlas);
    write_textured_glb(in.base, {atlas.face_uv, encode_png(atlas.image)}, args.output);
    baked = {{"size", args.atlas},
             {"charts", atlas.charts},
             {"texels_per_unit", atlas.texels_per_unit},
             {"faces", in.base.num_faces()}};
  } else {
    write_mesh(painted.mesh, args.output, WriteOptions{.cancel = &interrupt_token()});
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = paint_stats(painted, args.options, in.sample, *device);
  summary["base"] = args.base;
  summary["image"] = args.image;
  summary["output"] = args.output;
  summary["seconds"] = seconds;
  if (!baked.is_null()) summary["atlas"] = baked;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  if (!args.write_field.empty()) write_field_lines(args.write_field, painted.directions);
  progress.finish(summary.dump());
  if (progress_mode == ProgressMode::json) return;
  if (args.atlas != 0)
    std::printf("wrote %s: the base's %zu faces over a %d x %d texture, %zu vertices coloured from %s in %.1f s\n",
                args.output.c_str(), in.base.num_faces(), args.atlas, args.atlas, painted.mesh.num_vertices(),
                args.image.c_str(), seconds);
  else
    std::printf("wrote %s: %zu vertices coloured from %s (%d x %d) in %.1f s\n", args.output.c_str(),
              painted.mesh.num_vertices(), args.image.c_str(), in.sample.width, in.sample.height, seconds);
}

}  // namespace

void add_paint_command(CLI::App& app) {
  auto args = std::make_shared<PaintArgs>();
  CLI::App* cmd = app.add_subcommand(
      "paint", "Colour a base from an image sample, swept along synth's guidance field (Turk 2001)");
  add_paint_options(cmd, *args);
  cmd->callback([args] { run_paint(*args); });
}

}  // namespace meshquilt::cli
