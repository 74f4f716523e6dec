#include "surface/surface_quilting.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "quilt/broken_elements.h"
#include "surface/element_placement.h"
#include "quilt/hole_tracker.h"
#include "quilt/seed_finding.h"
#include "quilt/stage_timer.h"
#include "surface/surface_cells.h"

namespace meshquilt {
namespace {

struct SurfaceElement {
  std::vector<LocalVertex> vertices;
  std::vector<Tri> triangles;
  int32_t source = -1;
  Box3 bounds;  // of the base points under it, for culling
  // Its vertices in space (position_during_synthesis), filled when a patch first needs them as
  // an obstacle; a changed element is a new one, so they never go stale.
  std::vector<Vec3> in_space;
};

void update_bounds(SurfaceElement& e, const BaseSurface& base) {
  std::vector<Vec3> points;
  points.reserve(e.vertices.size());
  for (const LocalVertex& v : e.vertices) points.push_back(base.position(v.point));
  e.bounds = bounding_box(points);
}

// The part of an element inside a patch, and how its vertices map back.
struct ElementPart {
  int32_t element = -1;
  std::vector<int32_t> element_vertex;  // part vertex -> element vertex
  std::vector<uint8_t> face_in_part;    // #element faces
  std::vector<Vec3> plane_positions;    // part vertex -> where it was put in the plane
};

// Angle that turns the field direction at `seed` (mapped into the patch's plane) onto +x.
double field_angle(const BaseSurface& base, const SurfacePatch& patch, const SurfacePoint& seed, const Vec3& d) {
  const Tri& t = base.mesh.triangles[seed.face];
  const Vec3 e1 = base.mesh.positions[t[1]] - base.mesh.positions[t[0]];
  const Vec3 e2 = base.mesh.positions[t[2]] - base.mesh.positions[t[0]];
  // d = a e1 + b e2 in the face plane (least squares through the Gram matrix).
  const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
  const double r1 = glm::dot(d, e1), r2 = glm::dot(d, e2);
  const double det = g11 * g22 - g12 * g12;
  if (det <= 0.0) return 0.0;
  const double a = (r1 * g22 - r2 * g12) / det, b = (r2 * g11 - r1 * g12) / det;
  const glm::dvec2 origin = patch.to_plane({seed.face, glm::dvec2(0.0)});
  const glm::dvec2 u1 = patch.to_plane({seed.face, glm::dvec2(1.0, 0.0)}) - origin;
  const glm::dvec2 u2 = patch.to_plane({seed.face, glm::dvec2(0.0, 1.0)}) - origin;
  const glm::dvec2 planar = a * u1 + b * u2;
  return -std::atan2(planar.y, planar.x);
}

}  // namespace

SurfaceQuilt quilt_surface(const TriMesh& input_swatch, const TriMesh& base_mesh, const GuidanceField& field,
                      engine::Device& device, const SurfaceQuiltOptions& options, SurfaceQuiltStats* stats_out) {
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw OptionError("{scale} must be positive");
  if (options.shell_height < 0.0 || !std::isfinite(options.shell_height))
    throw OptionError("{shell_height} must not be negative");
  SurfaceQuiltStats stats;
  auto& seconds = stats.stage_seconds;
  const auto check_cancel = [&] {
    if (options.cancel) options.cancel->check();
  };

  const QuiltSwatch swatch = timed(seconds, "swatch", [&] { return prepare_swatch(input_swatch); });
  const BaseSurface base(base_mesh);
  stats.base_faces = static_cast<int>(base_mesh.num_faces());
  stats.diagonal = base.diagonal;
  // Base units per swatch unit.
  const double unit = options.scale * base.diagonal / std::max(swatch.extent.x, swatch.extent.y);
  double thickness = 0.0;
  for (const Vec3& p : swatch.mesh.positions) thickness = std::max(thickness, p.z);
  const double shell = options.shell_height > 0.0 ? options.shell_height : thickness * unit;
  // Heights of the swatch frame map onto [0, shell].
  const double height_unit = thickness > 0.0 ? shell / thickness : unit;
  stats.shell_height = shell;
  std::unique_ptr<SurfaceEmbedding> embedding;
  {
    StageTimer timer(seconds, "shell");
    embedding = options.embedding ? options.embedding(base, shell) : std::make_unique<NormalEmbedding>(base);
  }

  const double cell = std::min(swatch.extent.x, swatch.extent.y) / std::max(4, options.cells_across_swatch);
  const int swatch_nx = std::max(1, static_cast<int>(std::floor(swatch.extent.x / cell + 1e-9)));
  const int swatch_ny = std::max(1, static_cast<int>(std::floor(swatch.extent.y / cell + 1e-9)));
  const int sub_nx = std::clamp(static_cast<int>(std::lround(swatch_nx * options.sub_patch_fraction)), 1, swatch_nx);
  const int sub_ny = std::clamp(static_cast<int>(std::lround(swatch_ny * options.sub_patch_fraction)), 1, swatch_ny);
  stats.cell_size = cell * unit;

  MatchingOptions matching = options.matching;
  matching.lambda = options.lambda / swatch.mean_edge;
  PatchStepOptions step = options.step;
  step.correspondence.lambda = options.lambda / swatch.mean_edge;
  // The matcher's nearest-face grid, BVH and device buffers.
  const GeometryMatcher matcher = timed(seconds, "index", [&] { return GeometryMatcher(device, swatch.mesh, cell, matching); });
  stats.grid_source = matcher.grid_source();

  SurfaceCells cells;
  {
    StageTimer timer(seconds, "cells");
    cells = make_surface_cells(base, cell * unit);
  }
  const int total_cells = static_cast<int>(cells.centres.size());
  stats.cells = total_cells;
  double total_area = 0.0;
  for (double a : cells.areas) total_area += a;
  SeedFinder seeds(cells.neighbours);
  HoleTracker holes(seeds, options.seed_attempts);
  std::mt19937_64 rng(options.seed);

  std::vector<SurfaceElement> elements;
  std::vector<uint8_t> alive;
  // A patch must hold the footprint of any placement that covers the sub-patch: a disk of the
  // swatch's diagonal around the seed, plus a cell.
  const double full_radius = (glm::length(swatch.extent) + cell) * unit;
  double processed_area = 0.0;

  while (true) {
    check_cancel();
    std::optional<int> seed_cell;
    {
      StageTimer timer(seconds, "seed");
      seed_cell = seeds.next_seed();
    }
    if (!seed_cell || (options.max_patches > 0 && stats.patches >= options.max_patches)) break;
    const SurfacePoint seed = cells.centres[*seed_cell];

    SurfacePatch patch;
    double shrink = 1.0;
    {
      StageTimer timer(seconds, "patch");
      // A cell that a patch seeded on it did not cover is seeded again with twice the distortion
      // allowed: the same patch would fail the same way, and a patch shrunk below an element's
      // length places nothing (long yarns over the bunny's ears and cone-like vertices).
      const double max_distortion = options.max_area_distortion * std::ldexp(1.0, holes.tries(*seed_cell));
      for (int attempt = 0;; ++attempt) {
        patch = grow_conformal_patch(base, seed, full_radius * shrink);
        const bool good = patch.flipped_faces == 0 && patch.area_distortion <= max_distortion;
        if (good || attempt >= options.max_shrinks) break;
        shrink *= 0.75;
      }
      if (shrink < 1.0) ++stats.shrunk_patches;
      patch.transform(field_angle(base, patch, seed, field.at(base, seed)), 1.0 / unit);
      patch.index();
    }

    // The layer: parts of the elements that reach into the patch, in its plane.
    std::vector<PlaneElement> layer;
    std::vector<ElementPart> parts;
    std::vector<TriMesh> obstacles;
    {
      StageTimer timer(seconds, "layer");
      // Whatever can touch geometry placed over the patch: elements whose base points come within
      // two shell heights of the patch's faces (both may stand up to a shell height off the base).
      // The patch's faces reach a ring of faces past its radius, so its box, not the radius, decides.
      std::vector<Vec3> patch_points;
      for (int32_t v : patch.vertices) patch_points.push_back(base.mesh.positions[v]);
      Box3 reach = bounding_box(patch_points);
      reach.lo -= Vec3(2.0 * shell);
      reach.hi += Vec3(2.0 * shell);
      for (size_t e = 0; e < elements.size(); ++e) {
        if (!alive[e]) continue;
        SurfaceElement& element = elements[e];
        if (!element.bounds.overlaps(reach)) continue;
        std::vector<uint8_t> vertex_in(element.vertices.size());
        for (size_t v = 0; v < element.vertices.size(); ++v)
          vertex_in[v] = patch.face_index(element.vertices[v].point.face) >= 0;
        ElementPart part;
        part.element = static_cast<int32_t>(e);
        part.face_in_part.assign(element.triangles.size(), 0);
        std::vector<int32_t> part_vertex(element.vertices.size(), -1);
        std::vector<uint8_t> used_outside(element.vertices.size(), 0);
        PlaneElement plane;
        for (size_t f = 0; f < element.triangles.size(); ++f) {
          const Tri& t = element.triangles[f];
          const bool inside = vertex_in[t[0]] && vertex_in[t[1]] && vertex_in[t[2]];
          if (!inside) {
            for (int32_t v : t) used_outside[v] = 1;
            continue;
          }
          part.face_in_part[f] = 1;
          Tri local;
          for (int k = 0; k < 3; ++k) {
            int32_t& index = part_vertex[t[k]];
            if (index < 0) {
              index = static_cast<int32_t>(plane.mesh.positions.size());
              const LocalVertex& lv = element.vertices[t[k]];
              plane.mesh.positions.push_back(Vec3(patch.to_plane(lv.point), lv.height / height_unit));
              part.element_vertex.push_back(t[k]);
            }
            local[k] = index;
          }
          plane.mesh.triangles.push_back(local);
        }
        // The rest of the element stays where it is: an obstacle in space for this patch.
        if (std::find(part.face_in_part.begin(), part.face_in_part.end(), 0) != part.face_in_part.end()) {
          if (element.in_space.empty())
            for (const LocalVertex& lv : element.vertices)
              element.in_space.push_back(embedding->position_during_synthesis(lv.point, lv.height));
          TriMesh rest;
          for (size_t f = 0; f < element.triangles.size(); ++f) {
            if (part.face_in_part[f]) continue;
            const int32_t first = static_cast<int32_t>(rest.positions.size());
            for (int32_t v : element.triangles[f]) rest.positions.push_back(element.in_space[v]);
            rest.triangles.push_back({first, first + 1, first + 2});
          }
          obstacles.push_back(std::move(rest));
        }
        if (plane.mesh.triangles.empty()) continue;
        plane.pinned.assign(plane.mesh.positions.size(), 0);
        bool any_pinned = false;
        for (size_t k = 0; k < part.element_vertex.size(); ++k)
          if (used_outside[part.element_vertex[k]]) {
            plane.pinned[k] = 1;
            any_pinned = true;
          }
        if (!any_pinned) plane.pinned.clear();
        plane.bounds = xy_bounds(plane.mesh);
        plane.source = element.source;
        part.plane_positions = plane.mesh.positions;
        layer.push_back(std::move(plane));
        parts.push_back(std::move(part));
      }
    }

    PatchRequest request;
    const glm::dvec2 half = 0.5 * cell * glm::dvec2(sub_nx, sub_ny) * shrink;
    request.sub_patch = {-half, half};
    for (double ty = half.y - swatch.extent.y; ty <= -half.y + 1e-9 * cell; ty += cell)
      for (double tx = half.x - swatch.extent.x; tx <= -half.x + 1e-9 * cell; tx += cell)
        request.candidates.emplace_back(tx, ty);
    if (request.candidates.empty()) request.candidates.emplace_back(-0.5 * swatch.extent);
    {
      glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
      for (const glm::dvec2& p : patch.uv) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
      request.grid.origin = lo;
      request.grid.cell = cell;
      request.grid.nx = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / cell)));
      request.grid.ny = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / cell)));
    }
    request.inside_domain = [&patch](const glm::dvec2& p) { return patch.locate(p).has_value(); };
    request.whole_inputs_only = true;
    request.account_per_input = false;
    request.obstacles = std::move(obstacles);
    request.to_space = [&](const TriMesh& plane_mesh) {
      TriMesh placed;
      placed.triangles = plane_mesh.triangles;
      placed.positions.reserve(plane_mesh.positions.size());
      for (const Vec3& p : plane_mesh.positions) {
        const std::optional<SurfacePoint> at = patch.locate(glm::dvec2(p));
        const SurfacePoint point = at ? *at : patch.nearest(glm::dvec2(p));
        placed.positions.push_back(embedding->position_during_synthesis(point, p.z * height_unit));
      }
      return placed;
    };

    const size_t existing = layer.size();
    const PatchOutcome outcome =
        quilt_patch(layer, request, swatch, matcher, step, rng, stats.merges, seconds, options.cancel);

    {
      StageTimer timer(seconds, "layer");
      // Plane point -> local coordinates; a point outside every patch face goes to the nearest.
      const auto to_local = [&](const Vec3& p) {
        std::optional<SurfacePoint> at = patch.locate(glm::dvec2(p));
        if (!at) {
          ++stats.outside_vertices;
          at = patch.nearest(glm::dvec2(p));
        }
        return LocalVertex{*at, p.z * height_unit};
      };
      for (size_t l = 0; l < layer.size(); ++l) {
        const PlaneElement& plane = layer[l];
        if (!plane.changed) continue;
        if (l >= existing) {
          SurfaceElement added;
          added.source = plane.source;
          for (const Vec3& p : plane.mesh.positions) added.vertices.push_back(to_local(p));
          added.triangles = plane.mesh.triangles;
          update_bounds(added, base);
          elements.push_back(std::move(added));
          alive.push_back(1);
          continue;
        }
        // An element joined into another one (only whole elements are, never parts) is gone.
        if (!plane.alive) {
          alive[parts[l].element] = 0;
          continue;
        }
        // Put the new part back: faces outside the part stay; vertices that did not move keep
        // their local coordinates exactly (the pinned ones among them join the part to the rest).
        const ElementPart& part = parts[l];
        SurfaceElement& element = elements[part.element];
        std::unordered_map<Vec3, int32_t, ExactPositionHash> unmoved;
        for (size_t k = 0; k < part.element_vertex.size(); ++k)
          unmoved.emplace(part.plane_positions[k], part.element_vertex[k]);
        SurfaceElement rebuilt;
        rebuilt.source = plane.source;
        std::vector<int32_t> kept_index(element.vertices.size(), -1);
        const auto keep = [&](int32_t v) {
          if (kept_index[v] < 0) {
            kept_index[v] = static_cast<int32_t>(rebuilt.vertices.size());
            rebuilt.vertices.push_back(element.vertices[v]);
          }
          return kept_index[v];
        };
        for (size_t f = 0; f < element.triangles.size(); ++f) {
          if (part.face_in_part[f]) continue;
          const Tri& t = element.triangles[f];
          rebuilt.triangles.push_back({keep(t[0]), keep(t[1]), keep(t[2])});
        }
        std::vector<int32_t> new_index(plane.mesh.positions.size());
        for (size_t k = 0; k < plane.mesh.positions.size(); ++k) {
          const auto it = unmoved.find(plane.mesh.positions[k]);
          if (it != unmoved.end()) {
            new_index[k] = keep(it->second);
          } else {
            new_index[k] = static_cast<int32_t>(rebuilt.vertices.size());
            rebuilt.vertices.push_back(to_local(plane.mesh.positions[k]));
          }
        }
        for (const Tri& t : plane.mesh.triangles)
          rebuilt.triangles.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
        update_bounds(rebuilt, base);
        element = std::move(rebuilt);
      }
    }

    {
      StageTimer timer(seconds, "seed");
      for (int32_t f : patch.faces)
        for (int32_t c = cells.face_offsets[f]; c < cells.face_offsets[f + 1]; ++c) {
          if (seeds.processed(c)) continue;
          if (!outcome.covers(request.grid, patch.to_plane(cells.centres[c]))) continue;
          seeds.mark_processed(c);
          processed_area += cells.areas[c];
        }
      const bool was_processed = seeds.processed(*seed_cell);
      holes.attempted(*seed_cell);
      if (!was_processed && seeds.processed(*seed_cell)) processed_area += cells.areas[*seed_cell];
    }
    ++stats.patches;
    if (options.progress)
      options.progress({processed_area, total_area, total_cells - seeds.unprocessed_count(), total_cells, stats.patches});
  }

  std::vector<TriMesh> embedded(elements.size());
  {
    StageTimer timer(seconds, "embed");
    std::vector<LocalVertex> vertices;
    std::vector<Tri> triangles;
    std::vector<int32_t> face_element;
    std::vector<size_t> placed;  // element of each placed one
    for (size_t e = 0; e < elements.size(); ++e) {
      if (!alive[e]) continue;
      const auto first = static_cast<int32_t>(vertices.size());
      vertices.insert(vertices.end(), elements[e].vertices.begin(), elements[e].vertices.end());
      for (const Tri& t : elements[e].triangles) {
        triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
        face_element.push_back(static_cast<int32_t>(placed.size()));
      }
      placed.push_back(e);
    }
    const ElementPlacement placement = place_elements(*embedding, vertices, triangles, face_element);
    stats.synthesis_map_elements = placement.moved_elements();
    size_t next = 0;
    for (const size_t e : placed) {
      TriMesh& mesh = embedded[e];
      const auto begin = placement.positions.begin() + static_cast<std::ptrdiff_t>(next);
      next += elements[e].vertices.size();
      mesh.positions.assign(begin, placement.positions.begin() + static_cast<std::ptrdiff_t>(next));
      mesh.triangles = elements[e].triangles;
    }
  }
  if (options.cleanup) {
    StageTimer timer(seconds, "cleanup");
    std::vector<const TriMesh*> meshes;
    for (const TriMesh& m : embedded) meshes.push_back(&m);
    const BrokenElements removed = remove_broken_elements(meshes, swatch.closed_elements, alive);
    stats.dropped_open = removed.open;
    stats.dropped_intersecting = removed.intersecting;
    stats.intersecting_face_pairs = removed.intersecting_face_pairs;
  }
  stats.dropped_elements = stats.dropped_open + stats.dropped_intersecting;

  const HoleSummary hole_summary = holes.summary(cells.neighbours, cells.areas);
  stats.holes = hole_summary.holes;
  stats.hole_cells = hole_summary.cells;
  stats.hole_area = hole_summary.area;
  stats.largest_hole_area = hole_summary.largest_area;
  stats.covered_area = processed_area - stats.hole_area;

  std::vector<TriMesh> kept;
  std::vector<int32_t> kept_sources;
  SurfaceQuilt result;
  for (size_t e = 0; e < elements.size(); ++e)
    if (alive[e]) {
      kept.push_back(std::move(embedded[e]));
      kept_sources.push_back(elements[e].source);
      result.local.insert(result.local.end(), elements[e].vertices.begin(), elements[e].vertices.end());
    }
  result.mesh = join_elements(kept);
  result.mesh.sources.resize(result.mesh.num_faces());
  for (size_t f = 0; f < result.mesh.num_faces(); ++f) result.mesh.sources[f] = kept_sources[result.mesh.elements[f]];
  if (stats_out) *stats_out = stats;
  return result;
}

}  // namespace meshquilt
