#include "quilt/patch_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <functional>
#include <unordered_set>

#include <glm/geometric.hpp>

#include <tbb/parallel_for.h>

#include "mesh/border_cut.h"
#include "mesh/measures.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "quilt/lattice_copies.h"
#include "quilt/layer_collisions.h"
#include "quilt/quilt_policies.h"
#include "spatial/intersecting_pairs.h"
#include "quilt/stage_timer.h"

namespace meshquilt {
namespace {

TriMesh translated(const TriMesh& mesh, const glm::dvec2& t) {
  TriMesh out = mesh;
  for (Vec3& p : out.positions) p += Vec3(t, 0.0);
  return out;
}

// True when every pinned vertex of `before` is still a vertex of `after`, at its exact position.
bool keeps_pinned(const PlaneElement& before, const TriMesh& after) {
  if (before.pinned.empty()) return true;
  std::unordered_set<Vec3, ExactPositionHash> positions(after.positions.begin(), after.positions.end());
  for (size_t v = 0; v < before.pinned.size(); ++v)
    if (before.pinned[v] && !positions.count(before.mesh.positions[v])) return false;
  return true;
}

// Points and normals of the output vertices inside the sub-patch: what the swatch must match.
void sub_patch_samples(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& local, const Rect2& sub_patch,
                       std::vector<Vec3>& points, std::vector<Vec3>& normals) {
  for (int32_t k : local) {
    const PlaneElement& e = layer[k];
    if (!e.alive || !e.bounds.overlaps(sub_patch)) continue;
    const std::vector<Vec3> n = vertex_normals(e.mesh);
    for (size_t v = 0; v < e.mesh.num_vertices(); ++v) {
      if (!sub_patch.contains(e.mesh.positions[v])) continue;
      points.push_back(e.mesh.positions[v]);
      normals.push_back(n[v]);
    }
  }
}

// Marks the window's cells touched by each face's x-y bounding box (clamped to the grid first, so
// geometry past the grid marks its border cells).
void rasterize_faces(const TriMesh& m, const PlaneGrid& grid, const CellWindow& window, std::vector<uint8_t>& cells) {
  for (const Tri& f : m.triangles) {
    const Vec3 &a = m.positions[f[0]], &b = m.positions[f[1]], &c = m.positions[f[2]];
    const int ylo = std::max(grid.row(std::min({a.y, b.y, c.y})), window.y0);
    const int yhi = std::min(grid.row(std::max({a.y, b.y, c.y})), window.y1);
    const int xlo = std::max(grid.column(std::min({a.x, b.x, c.x})), window.x0);
    const int xhi = std::min(grid.column(std::max({a.x, b.x, c.x})), window.x1);
    for (int y = ylo; y <= yhi; ++y)
      for (int x = xlo; x <= xhi; ++x) cells[window.index(x, y)] = 1;
  }
}

// Grows a cell mask by one cell in every direction, within the window: exact at cells at least
// one cell inside the window's edges (and along edges the grid shares).
std::vector<uint8_t> dilated(const std::vector<uint8_t>& cells, const CellWindow& window) {
  std::vector<uint8_t> out = cells;
  for (int y = window.y0; y <= window.y1; ++y)
    for (int x = window.x0; x <= window.x1; ++x) {
      if (!cells[window.index(x, y)]) continue;
      for (int v = std::max(window.y0, y - 1); v <= std::min(window.y1, y + 1); ++v)
        for (int u = std::max(window.x0, x - 1); u <= std::min(window.x1, x + 1); ++u) out[window.index(u, v)] = 1;
    }
  return out;
}

// Cells whose centre lies inside the footprint, one cell away from its edges inside the domain,
// and where the placed swatch's geometry is accounted for: every placed input over the cell has
// its representative (the element it was added as, merged into or yielded to) within a cell of
// it, and an input that has none (refused as a whole; or every input, when `representative` is
// empty) at least some kept geometry. So a weft
// that yielded to an output weft ending short of it leaves its cells uncovered even where warps
// lie over them, and the driver seeds there again. Cells without swatch geometry are covered
// inside its outline, and outside it (a turned swatch's corners) only near kept geometry.
// Swatch elements at the patch's translation that were left out (`left_out`: centred past the
// domain's edge, or crossing a surface patch's edge) are accounted for where kept geometry lies
// within part of their width: half, or a quarter where a patch seeded again could place them
// (request.reachable), so a wider bare strip there is seeded again. Without this, the cells under a yarn that did not
// fit in a surface patch counted as covered and stayed bare (a tenth of the bunny under the
// small weave).
std::vector<uint8_t> covered_cells(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& local,
                                   const std::vector<TriMesh>& placed,
                                   const std::vector<int32_t>& representative, const std::vector<TriMesh>& left_out,
                                   const std::vector<int32_t>& left_out_source, const Rect2& footprint,
                                   const QuiltSwatch& swatch, const PlaneGrid& grid, const PatchRequest& request,
                                   CellWindow& covered_window) {
  const std::function<bool(const glm::dvec2&)>& inside_domain = request.inside_domain;
  // Only cells under the footprint can be covered; what decides them lies within r cells of
  // them, r the most dilations below (1, or a left-out element's reach).
  const int x0 = grid.column(footprint.lo.x), x1 = grid.column(footprint.hi.x);
  const int y0 = grid.row(footprint.lo.y), y1 = grid.row(footprint.hi.y);
  std::vector<int> half_widths;
  int reach = 1;
  for (size_t m = 0; m < left_out.size(); ++m) {
    const int32_t k = left_out_source[m];
    const Rect2& b = swatch.element_bounds[k];
    const glm::dvec2 size = b.hi - b.lo;
    // Across a surface patch's edge, by its bounds, half of it; at the plane's edge, by its
    // narrowest width (a diagonal yarn's bounds are nearly as wide as it is long), a quarter
    // where a patch seeded again could place it.
    const bool reachable = request.reachable && request.reachable(0.5 * (b.lo + b.hi) + footprint.lo);
    const double width = request.whole_inputs_only ? std::min(size.x, size.y) : swatch.element_widths[k];
    half_widths.push_back(std::max(1, static_cast<int>((reachable ? 0.25 : 0.5) * width / grid.cell)));
    reach = std::max(reach, half_widths.back());
  }
  const CellWindow window{std::max(0, x0 - reach), std::max(0, y0 - reach), std::min(grid.nx - 1, x1 + reach),
                          std::min(grid.ny - 1, y1 + reach)};
  const size_t count = window.size();
  std::vector<uint8_t> kept(count, 0), unaccounted(count, 0);
  for (int32_t k : local)
    if (layer[k].alive && layer[k].bounds.overlaps(footprint)) rasterize_faces(layer[k].mesh, grid, window, kept);
  // Kept geometry within one cell counts: neighbouring patches register their elements a little
  // apart, and a cell between a kept element and where the swatch had one is not a hole.
  const std::vector<uint8_t> near_kept = dilated(kept, window);
  // The inputs grouped by what must account for them (-1: any kept geometry), one raster each.
  std::map<int32_t, std::vector<uint8_t>> inputs_of;
  for (size_t i = 0; i < placed.size(); ++i) {
    int32_t r = representative.empty() ? -1 : representative[i];
    if (r >= 0 && !layer[r].alive) r = -1;
    auto [it, fresh] = inputs_of.try_emplace(r, count, 0);
    rasterize_faces(placed[i], grid, window, it->second);
  }
  for (const auto& [r, input] : inputs_of) {
    std::vector<uint8_t> near_representative;
    if (r >= 0) {
      std::vector<uint8_t> own(count, 0);
      rasterize_faces(layer[r].mesh, grid, window, own);
      near_representative = dilated(own, window);
    }
    const std::vector<uint8_t>& accounted = r >= 0 ? near_representative : near_kept;
    for (size_t k = 0; k < count; ++k)
      if (input[k] && !accounted[k]) unaccounted[k] = 1;
  }
  std::map<int, std::vector<uint8_t>> near_kept_within;  // kept geometry grown by r cells, by r
  // One left out wholly past the grid marks the grid's border cells (rows and columns clamp): the
  // swatch continues past that edge, so the edge too needs kept geometry near it. On the bunny
  // with a guidance field this keeps wefts closer to the field over seeds 1-6 (mean angle 15.8
  // degrees, 10.5 where the field is calm) than marking nothing (16.9, 13.1).
  for (size_t m = 0; m < left_out.size(); ++m) {
    const int r = half_widths[m];
    auto [it, fresh] = near_kept_within.try_emplace(r);
    if (fresh) {
      it->second = near_kept;
      for (int i = 1; i < r; ++i) it->second = dilated(it->second, window);
    }
    std::vector<uint8_t> input(count, 0);
    rasterize_faces(left_out[m], grid, window, input);
    for (size_t k = 0; k < count; ++k)
      if (input[k] && !it->second[k]) unaccounted[k] = 1;
  }
  // A cell next to the footprint's edge is where the next patch's seam goes, unless the domain
  // ends there.
  covered_window = CellWindow{x0, y0, x1, y1};
  std::vector<uint8_t> covered(covered_window.size(), 0);
  // Past the swatch's outline (a turned swatch's corners) it has no geometry by its shape, not
  // by its pattern: such a cell needs kept geometry within a cell.
  const double slack = std::max(0.5 * grid.cell, swatch.outline_slack);
  const auto settled = [&](const glm::dvec2& p) { return footprint.contains(p) || !inside_domain(p); };
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 centre = grid.origin + grid.cell * glm::dvec2(x + 0.5, y + 0.5);
      if (!footprint.contains(centre) || !inside_domain(centre) || unaccounted[window.index(x, y)]) continue;
      if (!near_kept[window.index(x, y)] && !swatch.outline.contains(centre - footprint.lo, slack)) continue;
      const double d = grid.cell;
      if (settled(centre + glm::dvec2(d, 0.0)) && settled(centre - glm::dvec2(d, 0.0)) &&
          settled(centre + glm::dvec2(0.0, d)) && settled(centre - glm::dvec2(0.0, d)))
        covered[covered_window.index(x, y)] = 1;
    }
  return covered;
}

// The overlap: under the footprint, where output geometry already exists
// (cells touched by an output face's bounding box). Returns the elements under the footprint.
std::vector<int32_t> occupy_cells(const std::vector<PlaneElement>& layer, const std::vector<int32_t>& local,
                                  const Rect2& footprint, const PlaneGrid& grid, const CellWindow& window,
                                  std::vector<uint8_t>& occupied) {
  std::vector<int32_t> affected;
  occupied.assign(window.size(), 0);
  for (int32_t i : local) {
    if (!layer[i].alive || !layer[i].bounds.overlaps(footprint)) continue;
    affected.push_back(i);
    rasterize_faces(layer[i].mesh, grid, window, occupied);
  }
  return affected;
}

// Eq. 5 and 6: both sides of each partner pair move toward c = (v_out + h_in) / 2. Pinned output
// vertices are held where they are.
void deform_partners(std::vector<TriMesh>& outs, const std::vector<const PlaneElement*>& out_sources,
                     std::vector<TriMesh>& inputs, const Correspondences& corr,
                     const std::vector<const ElementRelation*>& partners, double max_pair_distance,
                     const DeformationOptions& options) {
  std::vector<std::vector<VertexConstraint>> out_constraints(outs.size());
  std::vector<std::vector<FaceConstraint>> in_constraints(inputs.size());
  for (const ElementRelation* r : partners) {
    for (int32_t k : r->pairs) {
      const VertexFacePair& p = corr.pairs[k];
      // Where one element ends inside the overlap (a yarn's cap), the other's vertices past
      // that end pair with the cap; pulling them toward it would bend the yarn.
      if (p.distance > max_pair_distance) continue;
      const Vec3 target = 0.5 * (outs[p.out_element].positions[p.out_vertex] + p.closest);
      out_constraints[p.out_element].push_back({p.out_vertex, target});
      in_constraints[p.in_element].push_back({p.in_face, p.barycentric, target});
    }
  }
  // Each element's solve is its own: they run side by side.
  tbb::parallel_for(size_t{0}, outs.size(), [&](size_t o) {
    if (out_constraints[o].empty()) return;
    const std::vector<uint8_t>& pinned = out_sources[o]->pinned;
    for (size_t v = 0; v < pinned.size(); ++v)
      if (pinned[v]) out_constraints[o].push_back({static_cast<int32_t>(v), outs[o].positions[v]});
    std::vector<Vec3> moved = deform_with_vertex_constraints(outs[o], out_constraints[o], options);
    for (size_t v = 0; v < pinned.size(); ++v)
      if (pinned[v]) moved[v] = outs[o].positions[v];
    outs[o].positions = std::move(moved);
  });
  tbb::parallel_for(size_t{0}, inputs.size(), [&](size_t i) {
    if (!in_constraints[i].empty())
      inputs[i].positions = deform_with_face_constraints(inputs[i], in_constraints[i], options);
  });
}

}  // namespace

bool PatchOutcome::covers(const PlaneGrid& grid, const glm::dvec2& p) const {
  const glm::dvec2 local = (p - grid.origin) / grid.cell;
  if (local.x < 0.0 || local.y < 0.0 || local.x >= grid.nx || local.y >= grid.ny) return false;
  return covers_cell(grid.column(p.x), grid.row(p.y));
}

int PlaneGrid::column(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - origin.x) / cell)), 0, nx - 1);
}

int PlaneGrid::row(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - origin.y) / cell)), 0, ny - 1);
}

namespace {

// The swatch placed at the patch's translation: the inputs (elements whose centre lies in the
// domain; on a surface, that lie wholly in it) and those left out. Those left out still lie over
// the patch's cells: the swatch is not empty there, so those cells need kept geometry near them
// to count as covered (see covered_cells), and a later patch seeded there places them.
struct PlacedSwatch {
  std::vector<TriMesh> inputs, left_out;
  std::vector<int32_t> input_source;     // the swatch element of each input
  std::vector<int32_t> left_out_source;  // and of each left out
};

PlacedSwatch place_swatch(const QuiltSwatch& swatch, const PatchRequest& request, const glm::dvec2& t) {
  PlacedSwatch placed;
  for (size_t k = 0; k < swatch.elements.size(); ++k) {
    const Rect2& b = swatch.element_bounds[k];
    TriMesh placed_element = translated(swatch.elements[k], t);
    const bool inside =
        request.inside_domain(0.5 * (b.lo + b.hi) + t) &&
        (!request.whole_inputs_only ||
         std::all_of(placed_element.positions.begin(), placed_element.positions.end(),
                     [&](const Vec3& p) { return request.inside_domain(glm::dvec2(p)); }));
    if (!inside) {
      placed.left_out.push_back(std::move(placed_element));
      placed.left_out_source.push_back(static_cast<int32_t>(k));
      continue;
    }
    placed.inputs.push_back(std::move(placed_element));
    placed.input_source.push_back(static_cast<int32_t>(k));
  }
  return placed;
}

// What the merge steps of one patch share.
struct MergeContext {
  std::vector<PlaneElement>& layer;
  const std::vector<int32_t>& affected;  // the layer element of each output element of the patch
  PlacedSwatch& swatch;
  const Correspondences& corr;
  const std::function<bool(const Vec3&)>& in_overlap;
  const MergeOptions& merging;
  LayerCollisions& collisions;
  MergeCounts& counts;
  bool covered_inputs_rejected = true;  // PatchRequest::reject_covered_inputs
  // Shapes before the deformation, per output element (empty: not deformed).
  std::vector<std::vector<Vec3>> undeformed;
  std::vector<uint8_t> out_partnered;  // per output element
  // What stands for each input in the layer once merged (see covered_cells); -1: nothing.
  std::vector<int32_t> representative;

  PlaneElement& element(int32_t out) { return layer[affected[out]]; }
  void reshaped(int32_t out) {
    collisions.forget(affected[out]);
    element(out).bounds = xy_bounds(element(out).mesh);
  }
};

// A deformation that pushes an output element into a neighbour is undone: the element keeps its
// shape and the merge works from there. The shape before is kept: a partner that is not merged
// after all gets it back, since the deformation only served the seam (repeated patches would
// otherwise bend it again and again).
void keep_deformations(MergeContext& ctx, std::vector<TriMesh>& outs) {
  ctx.undeformed.assign(outs.size(), {});
  for (size_t o = 0; o < outs.size(); ++o) {
    const auto out = static_cast<int32_t>(o);
    PlaneElement& e = ctx.element(out);
    if (outs[o].positions == e.mesh.positions) continue;
    ctx.undeformed[o] = e.mesh.positions;
    if (ctx.collisions.collides(outs[o], ctx.affected[o])) {
      ++ctx.counts.undone_deformations;
      continue;
    }
    e.mesh = std::move(outs[o]);
    ctx.reshaped(out);
    e.changed = true;
  }
}

// A partner left unmerged gets its shape from before the deformation back, unless that shape
// would now pass through an element merged or deformed since: the deformed shape was tested
// against those, the one before was not.
void restore_shape(MergeContext& ctx, int32_t out) {
  std::vector<Vec3>& before = ctx.undeformed[out];
  if (before.empty()) return;
  PlaneElement& target = ctx.element(out);
  TriMesh restored;
  restored.positions = before;
  restored.triangles = target.mesh.triangles;
  if (ctx.collisions.collides(restored, ctx.affected[out])) return;
  target.mesh.positions = std::move(before);
  ctx.reshaped(out);
}

// An input that bridges two output elements (a yarn placed across the gap between two pieces of
// one yarn) meets the second end to end: it joins that one too, by a second merge into it.
// Returns the layer element absorbed, or -1, with `replacement` merged into it.
int32_t bridge(MergeContext& ctx, const ElementRelation& partner, TriMesh& replacement) {
  const PlaneElement& target = ctx.element(partner.out_element);
  for (const ElementRelation& other : ctx.corr.relations) {
    if (other.in_element != partner.in_element || ctx.out_partnered[other.out_element]) continue;
    const int32_t second = ctx.affected[other.out_element];
    // Whole elements only: a part would leave the rest of its element behind.
    if (!ctx.layer[second].alive || !ctx.layer[second].pinned.empty() || !target.pinned.empty()) continue;
    MergeResult bridged = merge_elements(ctx.layer[second].mesh, replacement, ctx.in_overlap, ctx.merging);
    if (bridged.outcome != MergeOutcome::stitched ||
        ctx.collisions.collides(bridged.element, ctx.affected[partner.out_element], second))
      continue;
    replacement = std::move(bridged.element);
    return second;
  }
  return -1;
}

// Commits one merge into the layer, or refuses it: an element kept as it was, a result that
// loses a pinned vertex, or one that would pass through a neighbour (a seam where two patches'
// registrations disagree) leaves the output element as it was.
void commit_merge(MergeContext& ctx, const ElementRelation& partner, MergeResult merged) {
  PlaneElement& target = ctx.element(partner.out_element);
  ctx.representative[partner.in_element] = ctx.affected[partner.out_element];
  if (merged.outcome == MergeOutcome::kept_out) {
    ++ctx.counts.kept;
    restore_shape(ctx, partner.out_element);
    return;
  }
  TriMesh& replacement =
      merged.outcome == MergeOutcome::stitched ? merged.element : ctx.swatch.inputs[partner.in_element];
  if (!keeps_pinned(target, replacement)) {
    ++ctx.counts.refused_pinned;
    restore_shape(ctx, partner.out_element);
    return;
  }
  bool hits = ctx.collisions.collides(replacement, ctx.affected[partner.out_element]);
  int32_t absorbed = -1;
  if (hits && merged.outcome == MergeOutcome::stitched) {
    absorbed = bridge(ctx, partner, replacement);
    hits = absorbed < 0;
  }
  if (hits) {
    ++ctx.counts.refused_merges;
    restore_shape(ctx, partner.out_element);
    return;
  }
  if (absorbed >= 0) {
    ++ctx.counts.bridged;
    ctx.layer[absorbed].alive = false;
    ctx.layer[absorbed].changed = true;
  }
  if (merged.outcome == MergeOutcome::stitched) {
    ++ctx.counts.stitched;
  } else {
    ++ctx.counts.replaced;
    target.source = ctx.swatch.input_source[partner.in_element];
  }
  target.mesh = std::move(replacement);
  ctx.reshaped(partner.out_element);
  target.changed = true;
}

// Input elements not merged are added as they are, unless they lie wholly over existing output
// or would pass through it (an input that related to an element merged with another one).
void add_unmerged_inputs(MergeContext& ctx, const std::vector<uint8_t>& in_partnered, PatchOutcome& outcome) {
  std::vector<TriMesh>& inputs = ctx.swatch.inputs;
  for (size_t i = 0; i < inputs.size(); ++i) {
    if (in_partnered[i]) continue;
    bool all_overlap = ctx.covered_inputs_rejected;
    for (const Vec3& p : inputs[i].positions) all_overlap = all_overlap && ctx.in_overlap(p);
    const Rect2 b = xy_bounds(inputs[i]);
    if (all_overlap || ctx.collisions.collides(inputs[i], -1)) {
      ++ctx.counts.rejected_inputs;
      continue;
    }
    ctx.representative[i] = static_cast<int32_t>(ctx.layer.size());
    outcome.added.push_back(static_cast<int32_t>(ctx.layer.size()));
    PlaneElement added;
    added.mesh = std::move(inputs[i]);
    added.bounds = b;
    added.source = ctx.swatch.input_source[i];
    added.changed = true;
    ctx.layer.push_back(std::move(added));
  }
}

}  // namespace

PatchOutcome quilt_patch(std::vector<PlaneElement>& layer, const PatchRequest& request,
                         const QuiltSwatch& swatch, const GeometryMatcher& matcher,
                         const PatchStepOptions& options, std::mt19937_64& rng, MergeCounts& counts, std::map<std::string, double>& seconds, const CancelToken* cancel) {
  const auto check_cancel = [cancel] {
    if (cancel) cancel->check();
  };
  PatchOutcome outcome;
  std::vector<int32_t> local;
  if (request.near) {
    local = *request.near;
  } else {
    local.resize(layer.size());
    std::iota(local.begin(), local.end(), 0);
  }
  {
    StageTimer timer(seconds, "match");
    std::vector<Vec3> points, normals;
    sub_patch_samples(layer, local, request.sub_patch, points, normals);
    outcome.placement = matcher.match(points, normals, request.candidates, rng, request.refine);
  }
  check_cancel();
  const glm::dvec2 t = outcome.placement.translation;
  const Rect2 footprint{t, t + swatch.extent};
  outcome.footprint = footprint;

  PlacedSwatch placed_swatch = place_swatch(swatch, request, t);
  outcome.inputs = static_cast<int>(placed_swatch.inputs.size());
  const std::vector<TriMesh> placed = placed_swatch.inputs;

  const PlaneGrid& grid = request.grid;
  const CellWindow footprint_cells{grid.column(footprint.lo.x), grid.row(footprint.lo.y), grid.column(footprint.hi.x),
                                   grid.row(footprint.hi.y)};
  std::vector<uint8_t> occupied;
  std::vector<int32_t> affected = occupy_cells(layer, local, footprint, grid, footprint_cells, occupied);
  // The inputs that are an element already there stand for it and leave the step, and so does it.
  std::vector<int32_t> copy_of(placed.size(), -1);
  if (options.skip_lattice_copies) {
    StageTimer timer(seconds, "copies");
    copy_of = lattice_copies(layer, affected, placed, options.copy_tolerance * swatch.mean_edge);
    std::vector<uint8_t> held(layer.size(), 0);
    PlacedSwatch rest;
    rest.left_out = std::move(placed_swatch.left_out);
    rest.left_out_source = std::move(placed_swatch.left_out_source);
    for (size_t i = 0; i < placed.size(); ++i) {
      if (copy_of[i] >= 0) {
        held[copy_of[i]] = 1;
        continue;
      }
      rest.inputs.push_back(std::move(placed_swatch.inputs[i]));
      rest.input_source.push_back(placed_swatch.input_source[i]);
    }
    placed_swatch = std::move(rest);
    std::erase_if(affected, [&held](int32_t e) { return held[e] != 0; });
    if (request.contacts) {
      const std::vector<uint8_t> neighbour = lattice_neighbours(layer, affected, placed_swatch.input_source, swatch, t,
                                                                *request.contacts, options.copy_tolerance * swatch.mean_edge);
      for (size_t k = 0; k < affected.size(); ++k) held[affected[k]] = neighbour[k];
      std::erase_if(affected, [&held](int32_t e) { return held[e] != 0; });
    }
    counts.lattice_copies += static_cast<int>(placed.size() - placed_swatch.inputs.size());
  }
  std::vector<TriMesh>& inputs = placed_swatch.inputs;
  // The overlap does not end at the domain's edge: where an output element and an input both
  // hang over it, they must be cut and stitched there too, or the input keeps a stub past the
  // output's end that no seam can join (the edge cells' occupancy stands for what lies beyond).
  const std::function<bool(const Vec3&)> in_overlap = [&](const Vec3& p) {
    return footprint.contains(p) && occupied[footprint_cells.index(grid.column(p.x), grid.row(p.y))] != 0;
  };

  std::vector<TriMesh> outs;
  std::vector<const PlaneElement*> out_sources;
  for (int32_t i : affected) {
    outs.push_back(layer[i].mesh);
    out_sources.push_back(&layer[i]);
  }

  Correspondences corr;
  {
    StageTimer timer(seconds, "correspondence");
    corr = find_correspondences(outs, inputs, *swatch.faces, placed_swatch.input_source, t, in_overlap,
                                options.correspondence);
  }
  check_cancel();

  const double max_pair_distance = options.partner_distance * swatch.mean_edge;
  std::vector<uint8_t> in_partnered;
  const std::vector<const ElementRelation*> partners =
      choose_partners(corr, outs.size(), inputs.size(), max_pair_distance, in_partnered);
  {
    StageTimer timer(seconds, "deform");
    deform_partners(outs, out_sources, inputs, corr, partners, max_pair_distance, options.deformation);
  }
  check_cancel();

  StageTimer timer(seconds, "merge");
  LayerCollisions collisions(layer, request, local);
  MergeContext ctx{layer, affected, placed_swatch, corr, in_overlap, options.merging, collisions, counts,
                   request.reject_covered_inputs, {}, {}, {}};
  keep_deformations(ctx, outs);
  ctx.representative.assign(inputs.size(), -1);
  ctx.out_partnered.assign(outs.size(), 0);
  for (const ElementRelation* partner : partners) ctx.out_partnered[partner->out_element] = 1;
  // Each merge depends only on its partner's output element and input, which no commit before it
  // changes (partners are one to one; a bridge absorbs only an unpartnered element): the merges
  // run side by side, and are committed in order, since whether a result collides depends on what
  // was committed before it.
  std::vector<MergeResult> merges(partners.size());
  tbb::parallel_for(size_t{0}, partners.size(), [&](size_t k) {
    merges[k] = merge_elements(layer[affected[partners[k]->out_element]].mesh, inputs[partners[k]->in_element],
                               in_overlap, options.merging);
  });
  for (size_t k = 0; k < partners.size(); ++k) {
    check_cancel();
    commit_merge(ctx, *partners[k], std::move(merges[k]));
  }
  add_unmerged_inputs(ctx, in_partnered, outcome);
  std::vector<int32_t> representative = std::move(copy_of);
  for (size_t i = 0, rest = 0; i < representative.size(); ++i)
    if (representative[i] < 0) representative[i] = ctx.representative[rest++];
  if (!request.account_per_input) representative.clear();
  for (int32_t k : outcome.added) local.push_back(k);
  outcome.covered = covered_cells(layer, local, placed, representative, placed_swatch.left_out,
                                  placed_swatch.left_out_source, footprint, swatch, grid, request, outcome.window);
  return outcome;
}

}  // namespace meshquilt
