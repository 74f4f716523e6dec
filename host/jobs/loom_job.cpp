#include "jobs/loom_job.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/constants.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "edit/element_edit.h"
#include "swatch/weave_pattern.h"
#include "loom/exemplar_weave.h"
#include "jobs/repairs_json.h"
#include "mesh/base_mesh.h"
#include "mesh/swatch_frame.h"
#include "surface/disc_chart.h"
#include "loom/yarn_profile.h"

namespace meshquilt {

AssignmentMethod parse_assignment_method(const std::string& text) {
  if (text == "naive") return AssignmentMethod::naive;
  if (text == "greedy") return AssignmentMethod::greedy;
  if (text == "structured") return AssignmentMethod::structured;
  throw InputError("{method}: expected naive, greedy or structured, got '" + text + "'", ErrorKind::invalid_option);
}

void check_loom_request(const LoomRequest& r) {
  if (r.exemplars.empty()) throw InputError("{exemplar}: give at least one woven exemplar", ErrorKind::invalid_option);
  if (r.stations < 2 || r.stations > 64 || r.stations % 2 != 0)
    throw InputError("{stations}: expected an even number in 2..64, got " + std::to_string(r.stations),
                     ErrorKind::invalid_option);
  if (r.sides < 3 || r.sides > 64)
    throw InputError("{sides}: expected 3..64, got " + std::to_string(r.sides), ErrorKind::invalid_option);
  if (r.base && !(r.scale > 0.0 && r.scale <= 10.0))
    throw InputError("{scale}: expected a value in (0, 10], got " + std::to_string(r.scale), ErrorKind::invalid_option);
  if (r.base && (r.assignment_only || !r.ply_output.empty()))
    throw InputError("{base}: a draped fabric is woven whole; drop {assignment_only} or write another format than .ply",
                     ErrorKind::invalid_option);
  if (r.design.width < 1 || r.design.height < 1)
    throw InputError(r.design_name + ": an empty design", ErrorKind::invalid_option);
  const double crossings = static_cast<double>(r.design.width) * r.design.height;
  // The assignment; the yarns' stations (two pieces a crossing); the mesh unless streamed.
  double bytes = crossings * 64.0;
  if (!r.assignment_only) bytes += crossings * 2.0 * r.stations * (8.0 * (r.sides + 2) + 64.0);
  if (!r.assignment_only && r.ply_output.empty()) bytes += crossings * 2.0 * r.stations * r.sides * (2.0 * 16.0 + 24.0);
  check_memory_budget(bytes, r.design_name + " (" + std::to_string(r.design.height) + " x " +
                                 std::to_string(r.design.width) + " crossings)");
}

namespace {

std::array<uint8_t, 3> bytes_of(const glm::dvec3& rgb) {
  std::array<uint8_t, 3> out{};
  for (int k = 0; k < 3; ++k) out[k] = static_cast<uint8_t>(std::lround(255.0 * std::clamp(rgb[k], 0.0, 1.0)));
  return out;
}

std::string hex(const std::array<uint8_t, 3>& c) {
  char text[8];
  std::snprintf(text, sizeof text, "%02X%02X%02X", c[0], c[1], c[2]);
  return text;
}

}  // namespace

std::vector<ColourWeave> parse_colour_weaves(const std::string& text) {
  std::vector<ColourWeave> out;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string entry = text.substr(start, end - start);
    const size_t equals = entry.find('=');
    if (equals == std::string::npos)
      throw InputError("{weaves}: expected RRGGBB=WEAVE, got '" + entry + "'", ErrorKind::invalid_option);
    const std::vector<std::array<uint8_t, 3>> colour = parse_palette(entry.substr(0, equals));
    if (colour.size() != 1)
      throw InputError("{weaves}: expected one colour before '=', got '" + entry + "'", ErrorKind::invalid_option);
    out.push_back({colour[0], parse_weave_pattern(entry.substr(equals + 1))});
    start = end + 1;
  }
  if (out.empty()) throw InputError("{weaves}: no entries", ErrorKind::invalid_option);
  return out;
}

LoomDesign design_of(const ColourImage& image, const std::vector<ColourWeave>& weaves, const std::string& name) {
  LoomDesign d{image.height, image.width, {}};
  d.warp_over.reserve(static_cast<size_t>(image.width) * image.height);
  for (int r = 0; r < image.height; ++r)
    for (int c = 0; c < image.width; ++c) {
      if (weaves.empty()) {
        d.warp_over.push_back(luma(image.at(c, r)) < 0.5 ? 1 : 0);
        continue;
      }
      const std::array<uint8_t, 3> colour = bytes_of(image.at(c, r));
      const auto it = std::find_if(weaves.begin(), weaves.end(), [&](const ColourWeave& w) { return w.colour == colour; });
      if (it == weaves.end())
        throw InputError(name + ": pixel (" + std::to_string(c) + ", " + std::to_string(r) + ") is " + hex(colour) +
                             ", which {weaves} names no weave for",
                         ErrorKind::invalid_option);
      d.warp_over.push_back(it->pattern.over(c, -r) ? 1 : 0);
    }
  return d;
}

LoomOutcome run_loom(const LoomRequest& request, const std::function<void(double)>& progress) {
  const auto report = [&](double share) {
    if (progress) progress(share);
  };
  LoomOutcome out;
  out.design = design_of(request.design, request.weaves, request.design_name);
  YarnColours colours;
  if (request.warp_types.width > 0 || request.weft_types.width > 0) {
    // A yarn without a map takes grey.
    for (int c = 0; c < out.design.columns; ++c)
      colours.push_back(request.warp_types.width > 0 ? bytes_of(request.warp_types.at(c % request.warp_types.width, 0))
                                                      : std::array<uint8_t, 3>{160, 160, 160});
    for (int r = 0; r < out.design.rows; ++r)
      colours.push_back(request.weft_types.width > 0 ? bytes_of(request.weft_types.at(0, r % request.weft_types.height))
                                                      : std::array<uint8_t, 3>{160, 160, 160});
  }
  std::vector<ExemplarProfiles> profiles;
  std::vector<WeavePattern> patterns;
  nlohmann::json exemplars = nlohmann::json::array();
  for (size_t u = 0; u < request.exemplars.size(); ++u) {
    const std::string& name = request.exemplar_names[u];
    // Exemplars as exported (triangle soups, y up) are repaired and framed as swatches are: the
    // thinnest axis turned to z.
    MeshRepairs repairs;
    const TriMesh exemplar = orient_swatch(request.exemplars[u], name, &repairs);
    const ExemplarWeave weave = register_exemplar(exemplar, name);
    patterns.push_back(weave.pattern);
    exemplars.push_back({{"file", name},
                         {"warps", weave.pattern.warps},
                         {"wefts", weave.pattern.wefts},
                         {"pitch", {weave.pitch.x, weave.pitch.y}},
                         {"origin", {weave.origin.x, weave.origin.y}},
                         {"tilt_degrees", weave.tilt * 180.0 / kPi},
                         {"yarn_radius", weave.yarn_radius},
                         {"repairs", repairs_json(repairs)}});
    if (!request.assignment_only)
      profiles.push_back(profile_exemplar(exemplar, weave, request.stations, request.sides, name));
  }
  report(0.1);
  AssignmentOptions options;
  options.method = request.method;
  options.seed = request.seed;
  options.periodic = request.periodic;
  out.assignment = assign_blocks(out.design, patterns, options);
  const AssignmentScores scores = score_assignment(out.design, patterns, out.assignment, request.periodic);
  report(0.3);
  nlohmann::json stats = {{"design", {{"rows", out.design.rows}, {"columns", out.design.columns}}},
                          {"exemplars", exemplars},
                          {"assignment",
                           {{"method", request.method == AssignmentMethod::naive    ? "naive"
                                       : request.method == AssignmentMethod::greedy ? "greedy"
                                                                                    : "structured"},
                            {"correct", scores.correct},
                            {"consistent", scores.consistent},
                            {"continuous", scores.continuous},
                            {"continuous_along_warps", scores.continuous_along_warps}}}};
  if (!request.assignment_only) {
    size_t faces = 0, vertices = 0;
    if (request.base) {
      // Over a disc: the fabric's plane onto the base's one chart, its longer side `scale` base
      // diagonals, centred; heights along the base's normals, the fabric's underside just above it.
      MeshRepairs repairs;
      const TriMesh base = prepare_base(*request.base, request.base_name, &repairs);
      const BaseSurface surface(base);
      const DiscChart chart = disc_chart(surface, request.base_name);
      const glm::dvec2 pitch = profiles[0].weave.pitch;
      const glm::dvec2 extent(out.design.columns * pitch.x, out.design.rows * pitch.y);
      const double to_base = request.scale * surface.diagonal / std::max(extent.x, extent.y);
      const double gap = 0.02 * to_base * std::min(pitch.x, pitch.y);
      out.fabric = drape_fabric(
          out.design, out.assignment, profiles,
          [&](const Vec3& p) -> std::optional<Vec3> {
            const std::optional<SurfacePoint> at = chart.patch.locate((glm::dvec2(p) - 0.5 * extent) * to_base);
            if (!at) return std::nullopt;
            return surface.position(*at) + surface.normal(*at) * (p.z * to_base + gap);
          },
          colours, request.periodic);
      faces = out.fabric.mesh.num_faces();
      vertices = out.fabric.mesh.num_vertices();
      int32_t pieces = 0;
      for (int32_t e : out.fabric.mesh.elements) pieces = std::max(pieces, e + 1);
      stats["drape"] = {{"base", request.base_name},
                        {"scale", request.scale},
                        {"area_distortion", chart.area_distortion},
                        {"base_units_per_pitch", to_base * pitch.x},
                        {"yarn_pieces", pieces}};
    } else if (request.ply_output.empty()) {
      out.fabric = weave_fabric(out.design, out.assignment, profiles, colours, request.periodic);
      faces = out.fabric.mesh.num_faces();
      vertices = out.fabric.mesh.num_vertices();
    } else {
      const LoomFabricFile written =
          write_fabric_ply(out.design, out.assignment, profiles, request.ply_output, colours, request.periodic);
      out.fabric.grid = written.grid;
      faces = written.faces;
      vertices = written.vertices;
    }
    const LoomGrid& g = out.fabric.grid;
    stats["grid"] = {{"origin", {g.origin.x, g.origin.y}},
                     {"row_step", {g.row_step.x, g.row_step.y}},
                     {"column_step", {g.column_step.x, g.column_step.y}},
                     {"rows", g.rows},
                     {"columns", g.columns}};
    stats["periodic"] = request.periodic;
    out.stats["faces"] = faces;
    out.stats["vertices"] = vertices;
    out.stats["elements"] = request.base ? stats["drape"]["yarn_pieces"].get<int>() : g.rows + g.columns;
  }
  out.stats["loom"] = stats;
  report(1.0);
  return out;
}

RgbImage assignment_picture(const LoomAssignment& a, int exemplars, int pixels) {
  RgbImage image;
  image.width = a.columns * pixels;
  image.height = a.rows * pixels;
  image.rgb.assign(static_cast<size_t>(image.width) * image.height * 3, 0);
  for (int r = 0; r < a.rows; ++r)
    for (int c = 0; c < a.columns; ++c) {
      const LoomBlock& b = a.at(r, c);
      const double hue = 6.0 * b.exemplar / std::max(1, exemplars);
      const double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
      const glm::dvec3 rgb = hue < 1 ? glm::dvec3(1, x, 0) : hue < 2 ? glm::dvec3(x, 1, 0) : hue < 3 ? glm::dvec3(0, 1, x)
                           : hue < 4 ? glm::dvec3(0, x, 1) : hue < 5 ? glm::dvec3(x, 0, 1) : glm::dvec3(1, 0, x);
      const bool continues = r > 0 && a.at(r - 1, c).exemplar == b.exemplar && a.at(r - 1, c).x == b.x &&
                             a.at(r - 1, c).y == b.y + 1;
      const glm::dvec3 shade = continues ? 0.5 * rgb + glm::dvec3(0.5) : 0.6 * rgb;
      for (int y = r * pixels; y < (r + 1) * pixels; ++y)
        for (int x0 = c * pixels; x0 < (c + 1) * pixels; ++x0)
          for (int k = 0; k < 3; ++k)
            image.rgb[(static_cast<size_t>(y) * image.width + x0) * 3 + k] =
                static_cast<uint8_t>(std::lround(255.0 * shade[k]));
    }
  return image;
}

}  // namespace meshquilt
