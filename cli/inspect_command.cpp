// `meshquilt inspect MESH [--swatch S] [--plane | --base B [--shell-height H]] [--json]`: the
// quality report of a mesh (DESIGN.md section 8).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/error.h"
#include "inspect/inspect_report.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"

namespace meshquilt::cli {
namespace {

struct InspectArgs {
  std::filesystem::path mesh;
  std::filesystem::path swatch;
  std::filesystem::path base;
  bool plane = false;
  std::vector<double> region;
  double shell_height = 0.0;
  double scale = 0.0;
  bool json = false;
  bool rings = false;
  bool yarns = false;
  std::filesystem::path near_cones;
  double near_radius = 3.0;
};

// The cone points synth's --stats file lists.
std::vector<Vec3> read_cone_points(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot be read", ErrorKind::file_unreadable);
  const nlohmann::json stats = nlohmann::json::parse(in, nullptr, false);
  if (stats.is_discarded() || !stats.is_object() || !stats.contains("cone_points") || !stats["cone_points"].is_array())
    throw InputError(file.string() + ": not a synth --stats file over a base (no cone_points)", ErrorKind::invalid_option);
  std::vector<Vec3> points;
  for (const nlohmann::json& p : stats["cone_points"]) {
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
      throw InputError(file.string() + ": a cone point that is not three numbers", ErrorKind::invalid_option);
    points.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  return points;
}

}  // namespace

void add_inspect_command(CLI::App& app) {
  auto args = std::make_shared<InspectArgs>();
  std::ostringstream weld;
  weld << kWeldTolerance;
  auto* cmd = app.add_subcommand(
      "inspect",
      "Measure a mesh: faces and vertices after welding coincident vertices (within " + weld.str() +
          " x the bbox diagonal), elements (vertex-connected components) and how many are closed "
          "2-manifolds, boundary/non-manifold edges, pinched vertices, intersecting face pairs between and "
          "within elements; optionally element-size KS distances to a swatch, plane coverage, or base "
          "coverage and heights");
  cmd->add_option("MESH", args->mesh, "mesh to inspect (.obj .ply .off .stl)")->required();
  cmd->add_option("--swatch", args->swatch, "compare element area and extent distributions with this swatch");
  auto* plane = cmd->add_flag("--plane", args->plane,
                              "coverage of the x-y footprint (2% margin) on a grid of half the median "
                              "element's x-y extent, or with --swatch of the swatch's largest gap (so its "
                              "own holes are not missing cover)");
  auto* region = cmd->add_option("--region", args->region,
                                 "with --plane: cover this x-y rectangle X0,Y0,X1,Y1 (for example synth's "
                                 "plane_rect) instead of the footprint; parts past it do not count")
                     ->expected(4)
                     ->delimiter(',');
  region->needs(plane);
  auto* base = cmd->add_option("--base", args->base,
                               "base mesh: coverage of its area (within half the median element extent "
                               "of a vertex's foot, or with --swatch half the diagonal of the swatch's "
                               "largest gap and an edge) and signed heights in units of its bbox diagonal");
  auto* shell = cmd->add_option("--shell-height", args->shell_height,
                                "shell height H in base bbox diagonals; counts vertices below the base or above H")
                    ->check(CLI::PositiveNumber);
  shell->needs(base);
  plane->excludes(base);
  auto* scale = cmd->add_option("--scale", args->scale,
                                "with --rings, --swatch and --base: the scale synth was asked for; ring radii "
                                "are also reported over the radius it asks (p10, median, p90)")
                    ->check(CLI::PositiveNumber);
  scale->needs(base);
  cmd->add_flag("--rings", args->rings,
                "the link graph of the elements taken as rings (chain mail): links per ring, pieces, "
                "median ring radius; with --swatch its ratio to the swatch's and, with --plane or --base, "
                "missing rings");
  auto* near = cmd->add_option("--near-cones", args->near_cones,
                               "with --rings: synth's --stats file; also the links and sizes of the rings near "
                               "the layout's cones it lists");
  near->needs(cmd->get_option("--rings"));
  cmd->add_option("--near-radius", args->near_radius, "with --near-cones: how near, in median ring radii")
      ->check(CLI::PositiveNumber)
      ->capture_default_str()
      ->needs(near);
  cmd->add_flag("--yarns", args->yarns,
                "yarn lengths: each closed element taken as a tube (length A^2 / (4 pi V)); the "
                "length-weighted median, and with --swatch in swatch lengths");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the readable report");

  cmd->callback([args, shell, scale] {
    const TriMesh mesh = read_mesh(args->mesh);
    std::optional<TriMesh> swatch, base_mesh;
    // The swatch as synth reads it: repaired and turned into its frame.
    if (!args->swatch.empty()) swatch = orient_swatch(read_mesh(args->swatch), args->swatch.string());
    // The base as synth reads it: repaired and each part wound outward, so heights are measured
    // on the side synth grew the layer.
    if (!args->base.empty()) base_mesh = prepare_base(read_mesh(args->base), args->base.string());
    InspectOptions options;
    options.plane = args->plane;
    options.rings = args->rings;
    options.yarns = args->yarns;
    if (!args->near_cones.empty()) {
      options.near_points = read_cone_points(args->near_cones);
      options.near_radius = args->near_radius;
    }
    if (!args->region.empty())
      options.plane_options.region = {{args->region[0], args->region[1]}, {args->region[2], args->region[3]}};
    options.mesh_name = args->mesh.string();
    options.swatch_name = args->swatch.string();
    options.base_name = args->base.string();
    if (shell->count() > 0) options.shell_height = args->shell_height;
    if (scale->count() > 0) options.scale = args->scale;
    const InspectReport report =
        inspect_mesh(mesh, options, swatch ? &*swatch : nullptr, base_mesh ? &*base_mesh : nullptr);
    if (args->json) {
      std::cout << to_json(report).dump(2) << "\n";
    } else {
      std::cout << args->mesh.string() << "\n" << to_text(report);
    }
  });
}

}  // namespace meshquilt::cli
