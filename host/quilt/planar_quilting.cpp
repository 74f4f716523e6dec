#include "quilt/planar_quilting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <random>

#include <glm/geometric.hpp>

#include "error.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "quilt/seed_finding.h"
#include "quilt/stitching.h"
#include "spatial/intersecting_pairs.h"

namespace meshquilt {
namespace {

using Clock = std::chrono::steady_clock;

struct Rect {
  glm::dvec2 lo{0.0}, hi{0.0};
  bool contains(const Vec3& p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
  bool overlaps(const Rect& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
  }
};

Rect xy_bounds(const TriMesh& mesh) {
  Rect r{glm::dvec2(std::numeric_limits<double>::max()), glm::dvec2(std::numeric_limits<double>::lowest())};
  for (const Vec3& p : mesh.positions) {
    r.lo = glm::min(r.lo, glm::dvec2(p));
    r.hi = glm::max(r.hi, glm::dvec2(p));
  }
  return r;
}

// Area-weighted vertex normals: Eq. 1 compares them with the swatch's face normals.
std::vector<Vec3> vertex_normals(const TriMesh& mesh) {
  std::vector<Vec3> normals(mesh.num_vertices(), Vec3(0.0));
  for (const Tri& t : mesh.triangles) {
    const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                              mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  for (Vec3& n : normals) {
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : Vec3(0.0, 0.0, 1.0);
  }
  return normals;
}

TriMesh translated(const TriMesh& mesh, const glm::dvec2& t) {
  TriMesh out = mesh;
  for (Vec3& p : out.positions) p += Vec3(t, 0.0);
  return out;
}

// True when any face of `candidate` intersects a face of one of `others`.
bool collides(const TriMesh& candidate, const std::vector<const TriMesh*>& others) {
  if (others.empty()) return false;
  // One mesh of all parts (element id = part, the candidate is 0), built in place.
  TriMesh joined;
  const auto append = [&](const TriMesh& mesh, int32_t part) {
    const int32_t base = static_cast<int32_t>(joined.positions.size());
    joined.positions.insert(joined.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (const Tri& t : mesh.triangles) {
      joined.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      joined.elements.push_back(part);
    }
  };
  append(candidate, 0);
  for (size_t k = 0; k < others.size(); ++k) append(*others[k], static_cast<int32_t>(k + 1));
  const auto pairs = intersecting_face_pairs(joined, joined.elements, IntersectionScope::different_elements);
  for (const auto& [a, b] : pairs)
    if (joined.elements[a] == 0 || joined.elements[b] == 0) return true;
  return false;
}

class StageTimer {
 public:
  StageTimer(std::map<std::string, double>& seconds, const char* stage)
      : seconds_(seconds), stage_(stage), start_(Clock::now()) {}
  ~StageTimer() { seconds_[stage_] += std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  std::map<std::string, double>& seconds_;
  const char* stage_;
  Clock::time_point start_;
};

struct OutputElement {
  TriMesh mesh;
  Rect bounds;
  bool alive = true;
};

}  // namespace

TriMesh quilt_plane(const TriMesh& input_swatch, engine::Device& device,
                    const PlanarQuiltOptions& options, QuiltStats* stats_out) {
  if (!(options.width > 0.0) || !(options.height > 0.0))
    throw InputError("plane size must be positive", ExitCode::invalid_option);
  QuiltStats stats;
  auto& seconds = stats.stage_seconds;

  const TriMesh swatch = orient_swatch(input_swatch, "swatch");
  const Rect swatch_bounds = xy_bounds(swatch);
  const glm::dvec2 extent = swatch_bounds.hi - swatch_bounds.lo;
  const double cell = std::min(extent.x, extent.y) / std::max(4, options.cells_across_swatch);
  const Rect domain{glm::dvec2(0.0), glm::dvec2(options.width * extent.x, options.height * extent.y)};
  const int nx = std::max(1, static_cast<int>(std::ceil(domain.hi.x / cell - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil(domain.hi.y / cell - 1e-9)));
  const int swatch_nx = std::max(1, static_cast<int>(std::floor(extent.x / cell + 1e-9)));
  const int swatch_ny = std::max(1, static_cast<int>(std::floor(extent.y / cell + 1e-9)));
  const int sub_nx = std::clamp(static_cast<int>(std::lround(swatch_nx * options.sub_patch_fraction)), 1, std::min(nx, swatch_nx));
  const int sub_ny = std::clamp(static_cast<int>(std::lround(swatch_ny * options.sub_patch_fraction)), 1, std::min(ny, swatch_ny));
  stats.cells = nx * ny;
  stats.cell_size = cell;

  const std::vector<TriMesh> swatch_elements = split_elements(swatch);
  bool swatch_closed = true;
  for (const TriMesh& e : swatch_elements) swatch_closed = swatch_closed && inspect_surface(e).closed_manifold();

  double edge_sum = 0.0;
  for (const Tri& t : swatch.triangles)
    for (int k = 0; k < 3; ++k) edge_sum += glm::distance(swatch.positions[t[k]], swatch.positions[t[(k + 1) % 3]]);
  const double mean_edge = edge_sum / (3.0 * static_cast<double>(swatch.num_faces()));
  MatchingOptions matching = options.matching;
  matching.lambda = options.lambda / mean_edge;
  CorrespondenceOptions correspondence = options.correspondence;
  correspondence.lambda = options.lambda / mean_edge;

  GeometryMatcher matcher(device, swatch, cell, matching);
  SeedFinder seeds(nx, ny);
  std::mt19937_64 rng(options.seed);
  std::vector<OutputElement> output;

  auto column = [&](double x) { return std::clamp(static_cast<int>(std::floor(x / cell)), 0, nx - 1); };
  auto row = [&](double y) { return std::clamp(static_cast<int>(std::floor(y / cell)), 0, ny - 1); };

  while (true) {
    std::optional<int> seed_cell;
    {
      StageTimer timer(seconds, "seed");
      seed_cell = seeds.next_seed();
    }
    if (!seed_cell || (options.max_patches > 0 && stats.patches >= options.max_patches)) break;
    const int seed_x = *seed_cell % nx, seed_y = *seed_cell / nx;

    // Output-sub-patch: sub_nx x sub_ny cells around the seed, inside the domain.
    const int px = std::clamp(seed_x - sub_nx / 2, 0, nx - sub_nx);
    const int py = std::clamp(seed_y - sub_ny / 2, 0, ny - sub_ny);
    const Rect sub_patch{glm::dvec2(px * cell, py * cell), glm::dvec2((px + sub_nx) * cell, (py + sub_ny) * cell)};

    MatchResult placement;
    {
      StageTimer timer(seconds, "match");
      std::vector<Vec3> points, normals;
      for (const OutputElement& e : output) {
        if (!e.alive || !e.bounds.overlaps(sub_patch)) continue;
        const std::vector<Vec3> n = vertex_normals(e.mesh);
        for (size_t v = 0; v < e.mesh.num_vertices(); ++v) {
          if (!sub_patch.contains(e.mesh.positions[v])) continue;
          points.push_back(e.mesh.positions[v]);
          normals.push_back(n[v]);
        }
      }
      // Grid-unit translations for which the swatch covers the sub-patch entirely.
      std::vector<glm::dvec2> candidates;
      for (int ty = py + sub_ny - swatch_ny; ty <= py; ++ty)
        for (int tx = px + sub_nx - swatch_nx; tx <= px; ++tx)
          candidates.emplace_back(tx * cell, ty * cell);
      placement = matcher.match(points, normals, candidates, rng);
    }
    const glm::dvec2 t = placement.translation;
    const Rect footprint{t, t + extent};

    // The new patch: swatch elements at t whose centre lies in the domain.
    std::vector<TriMesh> inputs;
    for (const TriMesh& e : swatch_elements) {
      const Rect b = xy_bounds(e);
      const glm::dvec2 centre = 0.5 * (b.lo + b.hi) + t;
      if (domain.contains(Vec3(centre, 0.0))) inputs.push_back(translated(e, t));
    }

    // Overlap: under the footprint, where output geometry already exists (cells touched by an
    // output face's bounding box).
    std::vector<int32_t> affected;
    std::vector<uint8_t> occupied(static_cast<size_t>(nx) * ny, 0);
    for (size_t i = 0; i < output.size(); ++i) {
      if (!output[i].alive || !output[i].bounds.overlaps(footprint)) continue;
      affected.push_back(static_cast<int32_t>(i));
      const TriMesh& m = output[i].mesh;
      for (const Tri& f : m.triangles) {
        const Vec3 &a = m.positions[f[0]], &b = m.positions[f[1]], &c = m.positions[f[2]];
        for (int y = row(std::min({a.y, b.y, c.y})); y <= row(std::max({a.y, b.y, c.y})); ++y)
          for (int x = column(std::min({a.x, b.x, c.x})); x <= column(std::max({a.x, b.x, c.x})); ++x)
            occupied[static_cast<size_t>(y) * nx + x] = 1;
      }
    }
    const auto in_overlap = [&](const Vec3& p) {
      return footprint.contains(p) && domain.contains(p) && occupied[static_cast<size_t>(row(p.y)) * nx + column(p.x)] != 0;
    };

    std::vector<TriMesh> outs;
    for (int32_t i : affected) outs.push_back(output[i].mesh);

    Correspondences corr;
    {
      StageTimer timer(seconds, "correspondence");
      corr = find_correspondences(outs, inputs, in_overlap, correspondence);
    }

    // Merge partners, one to one, in decreasing order of shared pairs. Interlinked elements
    // (chain mail) relate to their linked neighbours too, but only through a few pairs where the
    // rings pass through each other; constraints from those would pull rings out of shape, so
    // deformation uses the partners' pairs only.
    std::vector<const ElementRelation*> partners;
    std::vector<uint8_t> in_partnered(inputs.size(), 0);
    {
      std::vector<uint8_t> out_partnered(outs.size(), 0);
      for (const ElementRelation& r : corr.relations) {
        if (out_partnered[r.out_element] || in_partnered[r.in_element]) continue;
        // Partners must coincide closely: a relation whose pairs are on average farther apart
        // than half an edge is a neighbour seen through a misregistered seam, not a twin, and
        // deforming or merging it would bend both out of shape.
        double distance = 0.0;
        for (int32_t k : r.pairs) distance += corr.pairs[k].distance;
        if (distance > options.partner_distance * mean_edge * static_cast<double>(r.pairs.size())) continue;
        out_partnered[r.out_element] = in_partnered[r.in_element] = 1;
        partners.push_back(&r);
      }
    }

    {
      // Deform both sides toward c = (v_out + h_in) / 2 (Eq. 5 and 6), from the partners' pairs.
      StageTimer timer(seconds, "deform");
      std::vector<std::vector<VertexConstraint>> out_constraints(outs.size());
      std::vector<std::vector<FaceConstraint>> in_constraints(inputs.size());
      for (const ElementRelation* r : partners) {
        for (int32_t k : r->pairs) {
          const VertexFacePair& p = corr.pairs[k];
          // Where one element ends inside the overlap (a yarn's cap), the other's vertices past
          // that end pair with the cap; pulling them toward it would bend the yarn.
          if (p.distance > options.partner_distance * mean_edge) continue;
          const Vec3 target = 0.5 * (outs[p.out_element].positions[p.out_vertex] + p.closest);
          out_constraints[p.out_element].push_back({p.out_vertex, target});
          in_constraints[p.in_element].push_back({p.in_face, p.barycentric, target});
        }
      }
      for (size_t o = 0; o < outs.size(); ++o)
        if (!out_constraints[o].empty())
          outs[o].positions = deform_with_vertex_constraints(outs[o], out_constraints[o], options.deformation);
      for (size_t i = 0; i < inputs.size(); ++i)
        if (!in_constraints[i].empty())
          inputs[i].positions = deform_with_face_constraints(inputs[i], in_constraints[i], options.deformation);
    }

    {
      StageTimer timer(seconds, "merge");
      // Elements near `mesh` in the output, but for output element `self`.
      const auto neighbours = [&](const TriMesh& mesh, int32_t self) {
        const Rect b = xy_bounds(mesh);
        std::vector<const TriMesh*> near;
        for (size_t k = 0; k < output.size(); ++k)
          if (output[k].alive && static_cast<int32_t>(k) != self && output[k].bounds.overlaps(b))
            near.push_back(&output[k].mesh);
        return near;
      };
      // A deformation that pushes an output element into a neighbour is undone: the element
      // keeps its shape and the merge works from there.
      for (size_t o = 0; o < outs.size(); ++o) {
        OutputElement& e = output[affected[o]];
        if (outs[o].positions != e.mesh.positions && collides(outs[o], neighbours(outs[o], affected[o]))) {
          ++stats.undone_deformations;
          continue;
        }
        e.mesh = std::move(outs[o]);
        e.bounds = xy_bounds(e.mesh);
      }
      for (const ElementRelation* partner : partners) {
        const ElementRelation& r = *partner;
        OutputElement& target = output[affected[r.out_element]];
        MergeResult merged = merge_elements(target.mesh, inputs[r.in_element], in_overlap, options.merging);
        if (merged.outcome == MergeOutcome::kept_out) {
          ++stats.kept;
          continue;
        }
        TriMesh& replacement = merged.outcome == MergeOutcome::stitched ? merged.element : inputs[r.in_element];
        // A merged element that would pass through a neighbour (a seam where two patches'
        // registrations disagree) is refused: the output element stays as it was.
        if (collides(replacement, neighbours(replacement, affected[r.out_element]))) {
          ++stats.refused_merges;
          continue;
        }
        ++(merged.outcome == MergeOutcome::stitched ? stats.stitched : stats.replaced);
        target.mesh = std::move(replacement);
        target.bounds = xy_bounds(target.mesh);
      }
      // Input elements not merged: added as they are, unless they lie wholly over existing output
      // or would pass through it (an input that related to an element merged with another one).
      for (size_t i = 0; i < inputs.size(); ++i) {
        if (in_partnered[i]) continue;
        bool all_overlap = true;
        for (const Vec3& p : inputs[i].positions) all_overlap = all_overlap && in_overlap(p);
        const Rect b = xy_bounds(inputs[i]);
        if (all_overlap || collides(inputs[i], neighbours(inputs[i], -1))) {
          ++stats.rejected_inputs;
          continue;
        }
        output.push_back({std::move(inputs[i]), b, true});
      }
    }

    // Cells wholly inside the footprint shrunk by one cell are done; the seed always is.
    {
      StageTimer timer(seconds, "seed");
      const int x0 = std::max(0, static_cast<int>(std::ceil(footprint.lo.x / cell - 1e-9)) + 1);
      const int x1 = std::min(nx, static_cast<int>(std::floor(footprint.hi.x / cell + 1e-9)) - 1);
      const int y0 = std::max(0, static_cast<int>(std::ceil(footprint.lo.y / cell - 1e-9)) + 1);
      const int y1 = std::min(ny, static_cast<int>(std::floor(footprint.hi.y / cell + 1e-9)) - 1);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) seeds.mark_processed(y * nx + x);
      seeds.mark_processed(*seed_cell);
    }
    ++stats.patches;
    if (options.progress)
      options.progress({nx * ny - seeds.unprocessed_count(), nx * ny, stats.patches});
  }

  // Clean-up (paper Section 4): an element that could not be made whole is removed, and counted.
  {
    StageTimer timer(seconds, "cleanup");
    std::vector<size_t> alive;
    for (size_t i = 0; i < output.size(); ++i)
      if (output[i].alive) alive.push_back(i);
    if (options.cleanup) {
      for (size_t i : alive) {
        if (swatch_closed && !inspect_surface(output[i].mesh).closed_manifold()) {
          output[i].alive = false;
          ++stats.dropped_open;
        }
      }
      // Of two intersecting elements the smaller goes.
      std::vector<TriMesh> parts;
      std::vector<size_t> part_of;
      for (size_t i : alive)
        if (output[i].alive) {
          parts.push_back(output[i].mesh);
          part_of.push_back(i);
        }
      const TriMesh joined = join_elements(parts);
      const auto pairs = intersecting_face_pairs(joined, joined.elements, IntersectionScope::different_elements);
      std::map<std::pair<int32_t, int32_t>, int> element_pairs;
      for (const auto& [a, b] : pairs)
        ++element_pairs[std::minmax(joined.elements[a], joined.elements[b])];
      for (const auto& [pair, count] : element_pairs) {
        OutputElement& a = output[part_of[pair.first]];
        OutputElement& b = output[part_of[pair.second]];
        if (!a.alive || !b.alive) continue;
        OutputElement& smaller = a.mesh.num_faces() < b.mesh.num_faces() ? a : b;
        smaller.alive = false;
        ++stats.dropped_intersecting;
      }
    }
  }

  stats.dropped_elements = stats.dropped_open + stats.dropped_intersecting;
  std::vector<TriMesh> kept;
  for (OutputElement& e : output)
    if (e.alive) kept.push_back(std::move(e.mesh));
  if (stats_out) *stats_out = stats;
  return join_elements(kept);
}

}  // namespace meshquilt
