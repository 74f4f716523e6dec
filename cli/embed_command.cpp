// `meshquilt embed --texture FILE --base MESH -o OUT`: places a layer written by
// `synth --write-texture` over a base with the same connectivity (a pose, a sculpt, a scale of the
// one it was made over) without synthesizing again (Section 3.2 of the paper, last paragraph).
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "repair_report.h"
#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "embed_frames.h"
#include "jobs/embed_job.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "shell/texture_file.h"
#include "shell/texture_placement.h"

namespace meshquilt::cli {
namespace {

struct EmbedArgs {
  std::string texture;
  std::string base;
  std::string output;
  std::string stats;
  std::string embed = "auto";
  std::string base_frames;
  std::string format = "ply";
  bool provenance = false;
};

void run_embed(const EmbedArgs& args) {
  if (!args.base_frames.empty()) {
    if (!args.base.empty()) throw InputError("--base and --base-frames: give one", ErrorKind::invalid_option);
    run_embed_frames(
        {args.texture, args.base_frames, args.output, args.embed, args.format, args.stats, args.provenance});
    return;
  }
  if (args.base.empty()) throw InputError("embed: give --base or --base-frames", ErrorKind::invalid_option);
  const auto start = std::chrono::steady_clock::now();
  check_mesh_output(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);
  const QuiltTexture texture = read_texture_file(args.texture);
  MeshRepairs repairs;
  const TriMesh base = prepare_base(read_mesh(args.base), args.base, &repairs);
  say_repairs(args.base, repairs, "parts");
  PlacedTexture placed = run_embed(texture, base, args.embed, args.texture, args.base);
  if (!args.provenance) placed.mesh.origins.clear();
  const TriMesh& out = placed.mesh;
  write_mesh(out, args.output);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = {{"texture", args.texture}, {"base", args.base}, {"output", args.output}};
  summary.update(embed_stats(placed));
  summary["seconds"] = seconds;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  std::printf("wrote %s: %zu faces in %.2f s\n", args.output.c_str(), out.num_faces(), seconds);
}

}  // namespace

void add_embed_command(CLI::App& app) {
  auto args = std::make_shared<EmbedArgs>();
  CLI::App* cmd = app.add_subcommand(
      "embed", "Place a layer written by `synth --write-texture` over a base with the same connectivity");
  cmd->add_option("--texture", args->texture, "texture-space file from synth --write-texture")->required();
  cmd->add_option("--base", args->base, "the base, edited (same faces and vertices, moved)");
  cmd->add_option("--base-frames", args->base_frames,
                  "a folder of base frames (same connectivity): one output frame each, -o being a folder");
  cmd->add_option("-o,--output", args->output, "output mesh (.ply, .obj, .off, .stl, .glb), or folder")
      ->required();
  cmd->add_flag(
      "--provenance", args->provenance,
      "write each vertex's swatch vertex (PLY `origin`, glTF `_ORIGIN`; texture files from version 2)");
  cmd->add_option("--format", args->format, "with --base-frames: ply, obj, off, stl or glb")
      ->capture_default_str();
  cmd->add_option("--stats", args->stats, "write statistics as JSON");
  cmd->add_option("--embed", args->embed, "auto (as synth embedded it), shell or normal (displacement)")
      ->capture_default_str();
  cmd->callback([args] { run_embed(*args); });
}

}  // namespace meshquilt::cli
