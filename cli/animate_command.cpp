// `meshquilt animate --quilt Q --swatch-frames DIR -o OUT/`: plays a swatch's animation on a
// synthesized result: each output vertex moves by its swatch vertex's displacement, turned and
// scaled into its own local frame (edit/swatch_animation.h). Over a moving base (a texture file
// with --base-frames) both motions add.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "edit/element_edit.h"
#include "edit/swatch_animation.h"
#include "embed_frames.h"
#include "jobs/animate_job.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "shell/texture_file.h"
#include "shell/texture_placement.h"
#include "texture_files.h"

namespace meshquilt::cli {
namespace {

namespace fs = std::filesystem;

struct AnimateArgs {
  std::string quilt, swatch_frames, swatch, output, base, base_frames, embed = "auto", format = "ply", stats;
  bool keep_all = false;
};

void run_animate(const AnimateArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const bool texture_in = is_texture_file(args.quilt);
  if (texture_in && args.base.empty() == args.base_frames.empty())
    throw InputError(args.quilt + ": a texture file needs --base or --base-frames",
                     ErrorKind::invalid_option);
  if (!texture_in && (!args.base.empty() || !args.base_frames.empty()))
    throw InputError("--base and --base-frames place a texture file (.mqt), not " + args.quilt,
                     ErrorKind::invalid_option);
  check_mesh_output("frame." + args.format);
  const std::vector<fs::path> swatch_frames = list_mesh_frames(args.swatch_frames);
  std::error_code error;
  fs::create_directories(args.output, error);
  check_writable(fs::path(args.output) / "frame");
  if (!args.stats.empty()) check_writable(args.stats);

  const TriMesh rest = read_mesh(args.swatch.empty() ? swatch_frames[0] : fs::path(args.swatch));
  const std::string rest_name = args.swatch.empty() ? swatch_frames[0].string() : args.swatch;
  // The result: a mesh with origins, or a texture file placed over one base or each base frame.
  TriMesh quilt;
  QuiltTexture texture;
  std::unique_ptr<BaseFrames> base_frames;
  if (texture_in) {
    texture = read_texture_file(args.quilt);
    if (texture.origins.empty())
      throw InputError(
          args.quilt + ": a version 1 texture file names no swatch vertices; synthesize it again",
          ErrorKind::invalid_option);
    base_frames = std::make_unique<BaseFrames>(
        args.base_frames.empty() ? std::vector<fs::path>{args.base} : list_mesh_frames(args.base_frames),
        texture);
  } else {
    quilt = read_mesh(args.quilt);
    if (quilt.elements.empty() && !quilt.origins.empty()) quilt.elements = face_components(quilt);
    check_animated_quilt(quilt, args.quilt);
  }
  const size_t count = std::max(swatch_frames.size(), base_frames ? base_frames->size() : size_t{0});
  std::vector<glm::dmat3> frames;
  size_t placed_for = static_cast<size_t>(-1);
  // Frame k: the result over its base frame, each vertex moved by its swatch vertex.
  const auto frame_mesh = [&](size_t k) {
    const fs::path& swatch_path = swatch_frames[k % swatch_frames.size()];
    const TriMesh swatch = read_mesh(swatch_path);
    check_swatch_frame(swatch.num_vertices(), rest.num_vertices(), swatch_path.string(), rest_name);
    const size_t base_k = base_frames ? std::min(k, base_frames->size() - 1) : 0;
    if (texture_in && placed_for != base_k) {
      quilt = place_texture(texture, base_frames->posed(base_k), args.embed, args.quilt).mesh;
      frames.clear();
      placed_for = base_k;
    }
    if (frames.empty()) frames = vertex_frames(quilt, rest.positions);
    TriMesh moved = quilt;
    moved.positions = animated_positions(quilt, frames, rest.positions, swatch.positions);
    if (texture_in) moved.origins.clear();
    return moved;
  };

  // Elements that meet another, or themselves, in any frame are left out of every frame (the
  // clean-up pass of synthesis, over time), unless --keep-all.
  const TriMesh first = frame_mesh(0);
  const MeetingElements meeting =
      meeting_elements(first, args.keep_all ? 0 : count,
                       [&](size_t k) { return k == 0 ? first.positions : frame_mesh(k).positions; });
  const std::vector<int32_t>& dropped = meeting.dropped;

  nlohmann::json per_frame = nlohmann::json::array();
  for (size_t k = 0; k < count; ++k) {
    const auto frame_start = std::chrono::steady_clock::now();
    TriMesh moved = frame_mesh(k);
    if (!dropped.empty()) moved = keep_faces(moved, faces_kept(moved.elements, dropped));
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04zu.", k);
    const fs::path out = fs::path(args.output) / (name + args.format);
    write_mesh(moved, out);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_start).count();
    per_frame.push_back({{"swatch", swatch_frames[k % swatch_frames.size()].string()},
                         {"output", out.string()},
                         {"seconds", seconds}});
    std::printf("frame %zu/%zu %s in %.2f s\n", k + 1, count, out.filename().string().c_str(), seconds);
    std::fflush(stdout);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.stats.empty())
  {
    nlohmann::json summary = {{"quilt", args.quilt}};
    summary.update(animate_stats(count, meeting));
    summary["seconds"] = seconds;
    summary["per_frame"] = per_frame;
    write_text_atomic(args.stats, summary.dump(2) + "\n");
  }
  std::printf(
      "wrote %zu frames to %s in %.2f s; %zu of %zu elements left out for meeting another or themselves\n",
      count, args.output.c_str(), seconds, dropped.size(), meeting.ids.size());
}

}  // namespace

void add_animate_command(CLI::App& app) {
  auto args = std::make_shared<AnimateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "animate",
      "Play a swatch animation on a result: each vertex follows its swatch vertex in its own frame");
  cmd->add_option("--quilt", args->quilt,
                  "a result written with synth --provenance, or its texture file (.mqt)")
      ->required();
  cmd->add_option("--swatch-frames", args->swatch_frames,
                  "folder of swatch frames (same vertices as the swatch)")
      ->required();
  cmd->add_option("--swatch", args->swatch,
                  "the swatch at rest, as synth used it (default: the first frame)");
  cmd->add_option("-o,--output", args->output, "folder for the output frames frame_NNNN.EXT")->required();
  cmd->add_option("--base", args->base, "with a .mqt: the base to place it over");
  cmd->add_option("--base-frames", args->base_frames,
                  "with a .mqt: a folder of base frames; both motions add");
  cmd->add_option("--embed", args->embed, "with a .mqt: auto, shell or normal")->capture_default_str();
  cmd->add_option("--format", args->format, "output frames: ply, obj, off, stl or glb")
      ->capture_default_str();
  cmd->add_flag("--keep-all", args->keep_all, "keep elements that meet another or themselves in some frame");
  cmd->add_option("--stats", args->stats, "write per-frame figures as JSON");
  cmd->callback([args] { run_animate(*args); });
}

}  // namespace meshquilt::cli
