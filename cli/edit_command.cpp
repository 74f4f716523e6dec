// `meshquilt edit IN -o OUT`: removes and recolours elements of a synthesized result (a mesh or a
// texture-space file), keeping every other element exactly as it was (Figure 9 of the paper).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "repair_report.h"
#include "atomic_file.h"
#include "commands.h"
#include "core/error.h"
#include "edit/element_edit.h"
#include "jobs/edit_job.h"
#include "edit/texture_edit.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "render/element_palette.h"
#include "shell/texture_file.h"
#include "shell/texture_placement.h"
#include "texture_files.h"

namespace meshquilt::cli {
namespace {

struct EditArgs {
  std::string input, output, stats, base, embed = "auto";
  std::string remove_elements, remove_sources, keep_sources;
  std::vector<double> box, sphere;
  double age = 0.0;
  uint64_t seed = 1;
  std::string color_by, palette;
};

// "3,5,10-20": ids and inclusive ranges.
std::vector<int32_t> parse_ids(const std::string& text, const std::string& option) {
  std::vector<int32_t> ids;
  if (text.empty()) return ids;
  size_t start = 0;
  const auto fail = [&] {
    throw InputError(option + ": expected ids and ranges like 3,5,10-20, got '" + text + "'",
                     ErrorKind::invalid_option);
  };
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string entry = text.substr(start, end - start);
    const size_t dash = entry.find('-', 1);
    try {
      size_t used = 0;
      const long first = std::stol(entry.substr(0, dash), &used);
      if (used != entry.substr(0, dash).size()) fail();
      long last = first;
      if (dash != std::string::npos) {
        last = std::stol(entry.substr(dash + 1), &used);
        if (used != entry.size() - dash - 1) fail();
      }
      if (first < 0 || last < first || last > (1L << 31) - 1 || last - first > 100000000) fail();
      for (long id = first; id <= last; ++id) ids.push_back(static_cast<int32_t>(id));
    } catch (const std::logic_error&) {
      fail();
    }
    start = end + 1;
  }
  return ids;
}

EditRequest request_of(const EditArgs& args) {
  EditRequest request;
  request.remove_elements = parse_ids(args.remove_elements, "--remove-elements");
  request.remove_sources = parse_ids(args.remove_sources, "--remove-source");
  request.keep_sources = parse_ids(args.keep_sources, "--keep-source");
  if (!args.box.empty()) request.remove_inside.push_back(box_region(args.box));
  if (!args.sphere.empty()) request.remove_inside.push_back(sphere_region(args.sphere));
  request.age = args.age;
  request.seed = args.seed;
  return request;
}

void run_edit(const EditArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const bool texture_in = is_texture_file(args.input);
  const bool texture_out = is_texture_file(args.output);
  const bool recolour = !args.color_by.empty() || !args.palette.empty();
  const ColorBy color_by = args.color_by.empty() ? ColorBy::element : parse_color_by(args.color_by);
  const auto palette =
      args.palette.empty() ? std::vector<std::array<uint8_t, 3>>{} : parse_palette(args.palette);
  if (texture_out && !texture_in)
    throw InputError(
        args.output + ": a texture-space file can only be edited from one (" + args.input + " is a mesh)",
        ErrorKind::invalid_option);
  if (texture_out && recolour)
    throw InputError(args.output + ": texture-space files keep no colours; write a mesh to recolour",
                     ErrorKind::invalid_option);
  if (texture_in && !texture_out && args.base.empty())
    throw InputError(args.input + ": placing a texture-space file as a mesh needs --base",
                     ErrorKind::invalid_option);
  const EditRequest request = request_of(args);
  if (!texture_out) check_mesh_output(args.output);
  check_writable(args.output);
  if (!args.stats.empty()) check_writable(args.stats);

  TriMesh mesh;
  QuiltTexture texture;
  if (texture_in) {
    texture = read_texture_file(args.input);
    if (!args.base.empty()) {
      MeshRepairs repairs;
      const TriMesh base = prepare_base(read_mesh(args.base), args.base, &repairs);
      say_repairs(args.base, repairs, "parts");
      check_texture_base(texture, base, args.base);
      mesh = place_texture(texture, base, args.embed, args.input).mesh;
      mesh.origins.clear();
    } else {
      mesh.triangles = texture.triangles;
      mesh.elements = texture.elements;
      mesh.sources = texture.sources;
    }
  } else {
    mesh = read_mesh(args.input);
    if (mesh.elements.empty()) mesh.elements = face_element_ids(mesh);
  }
  const EditOutcome edit = plan_edit(mesh, request, args.input);
  const EditCounts& counts = edit.counts;
  if (texture_out) {
    write_texture_file(args.output, keep_texture_faces(texture, edit.keep));
  } else {
    TriMesh out = keep_faces(mesh, edit.keep);
    if (recolour) out.colors = vertex_colors(out, color_by, palette);
    write_mesh(out, args.output);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = {{"input", args.input}, {"output", args.output}};
  summary.update(edit_stats(counts));
  summary["seconds"] = seconds;
  if (!args.stats.empty()) write_text_atomic(args.stats, summary.dump(2) + "\n");
  std::printf("wrote %s: %d of %d elements kept (%d removed)\n", args.output.c_str(), counts.kept,
              counts.elements, counts.elements - counts.kept);
}

}  // namespace

void add_edit_command(CLI::App& app) {
  auto args = std::make_shared<EditArgs>();
  CLI::App* cmd = app.add_subcommand(
      "edit",
      "Remove or recolour elements of a result (mesh or .mqt); other elements stay exactly as they were");
  cmd->add_option("IN", args->input, "a synthesized mesh (.ply .obj .off .stl) or texture file (.mqt)")
      ->required();
  cmd->add_option("-o,--output", args->output, "output mesh, or .mqt when IN is one")->required();
  cmd->add_option("--remove-elements", args->remove_elements, "element ids to remove: 3,5,10-20");
  cmd->add_option("--remove-source", args->remove_sources,
                  "remove every element copied from these swatch elements");
  cmd->add_option("--keep-source", args->keep_sources,
                  "keep only elements copied from these swatch elements");
  cmd->add_option("--remove-box", args->box,
                  "remove elements whose vertex mean lies in the box X0 Y0 Z0 X1 Y1 Z1")
      ->expected(6);
  cmd->add_option("--remove-sphere", args->sphere,
                  "remove elements whose vertex mean lies in the sphere X Y Z R")
      ->expected(4);
  cmd->add_option("--age", args->age, "remove this share of the elements at random (the paper's aging)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "seed of --age's choice")->capture_default_str();
  cmd->add_option("--color-by", args->color_by,
                  "element or source: vertex colours per element or per source");
  cmd->add_option("--palette", args->palette,
                  "colours RRGGBB,RRGGBB,... taken in turn by id (default: render's)");
  cmd->add_option("--base", args->base,
                  "with IN a .mqt: the base to place it over (needed for a mesh out, or boxes)");
  cmd->add_option("--embed", args->embed, "with --base: auto, shell or normal")->capture_default_str();
  cmd->add_option("--stats", args->stats, "write what was removed as JSON");
  cmd->callback([args] { run_edit(*args); });
}

}  // namespace meshquilt::cli
