#include "quilt/merging/stitching.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "mesh/measures.h"
#include "mesh/topology.h"
#include "quilt/merging/seam_alignment.h"
#include "quilt/element_deformation.h"
#include "spatial/box_grid.h"
#include "spatial/segment_distance.h"
#include "spatial/triangle_intersection.h"

namespace meshquilt {
namespace {

//! Distance from p to the closed polyline through `points`.
double point_polyline(const Vec3& p, const std::vector<Vec3>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < points.size(); ++k)
    best = std::min(best, point_segment_distance(p, points[k], points[(k + 1) % points.size()]));
  return best;
}

//! The kept faces of a mesh as a compact mesh, with the vertex map old -> new (-1: dropped).
TriMesh extract(const TriMesh& mesh, const std::vector<uint8_t>& keep, std::vector<int32_t>& vmap,
                std::vector<int32_t>& fmap) {
  TriMesh part;
  vmap.assign(mesh.num_vertices(), -1);
  fmap.assign(mesh.num_faces(), -1);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!keep[f]) continue;
    Tri t;
    for (int k = 0; k < 3; ++k) {
      int32_t& m = vmap[mesh.triangles[f][k]];
      if (m < 0) {
        m = static_cast<int32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[mesh.triangles[f][k]]);
        if (!mesh.origins.empty()) part.origins.push_back(mesh.origins[mesh.triangles[f][k]]);
      }
      t[k] = m;
    }
    fmap[f] = static_cast<int32_t>(part.triangles.size());
    part.triangles.push_back(t);
  }
  return part;
}

StitchResult refuse(std::string why) {
  StitchResult r;
  r.failure = std::move(why);
  return r;
}

//! One side of the seam: the kept faces of an input as a compact mesh, its cut loops renumbered
//! into that mesh, and the positions of each loop's vertices.
struct SeamSide {
  TriMesh part;
  std::vector<CutLoop> loops;
  std::vector<std::vector<Vec3>> loop_points;
};

//! Cuts the kept faces out of `mesh` as side.part and carries `loops` (cut_loops of `mesh`) over.
void cut_out_side(const TriMesh& mesh, const std::vector<uint8_t>& keep, std::vector<CutLoop> loops, SeamSide& side) {
  std::vector<int32_t> vertex_map, face_map;
  side.part = extract(mesh, keep, vertex_map, face_map);
  side.loops = std::move(loops);
  side.loop_points.clear();
  for (CutLoop& loop : side.loops) {
    for (int32_t& v : loop.vertices) v = vertex_map[v];
    for (int32_t& f : loop.faces) f = face_map[f];
    std::vector<Vec3> points;
    for (int32_t v : loop.vertices) points.push_back(side.part.positions[v]);
    side.loop_points.push_back(std::move(points));
  }
}

//! Pairs the cut loops of the two sides one-to-one: each loop's nearest partner (mean distance of
//! its points to the other polyline) must choose it back. Returns the second-side partner of each
//! first-side loop, or an empty vector when the loops do not pair up. \pre both sides have L loops.
std::vector<int32_t> pair_loops(const SeamSide& first, const SeamSide& second) {
  const size_t count = first.loops.size();
  auto mean_distance = [](const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    double sum = 0.0;
    for (const Vec3& p : from) sum += point_polyline(p, to);
    return sum / static_cast<double>(from.size());
  };
  std::vector<int32_t> partner_of_first(count), partner_of_second(count);
  for (size_t i = 0; i < count; ++i) {
    double best_from_first = std::numeric_limits<double>::infinity(), best_from_second = best_from_first;
    for (size_t j = 0; j < count; ++j) {
      const double from_first = mean_distance(first.loop_points[i], second.loop_points[j]);
      if (from_first < best_from_first) best_from_first = from_first, partner_of_first[i] = static_cast<int32_t>(j);
      const double from_second = mean_distance(second.loop_points[i], first.loop_points[j]);
      if (from_second < best_from_second) best_from_second = from_second, partner_of_second[i] = static_cast<int32_t>(j);
    }
  }
  for (size_t i = 0; i < count; ++i)
    if (partner_of_second[partner_of_first[i]] != static_cast<int32_t>(i)) return {};
  return partner_of_first;
}

//! An aligned loop pair: which loops, and the second-side vertex of each aligned second-loop
//! position (the second loop reversed and rotated to start at `alignment`'s best start).
struct LoopPairPlan {
  int32_t first_loop = -1, second_loop = -1;
  std::vector<int32_t> second_vertices;
  Alignment alignment;
};

//! Aligns a first-side loop with its partner. The partner runs reversed so that both loops go the
//! same way along the seam (the parts lie on opposite sides of it, each to the left of its own
//! loop); its start is tried at the `start_candidates` vertices nearest to the first loop's start
//! and the cheapest alignment kept. Returns an empty string, or why the pair cannot be aligned.
std::string align_loop_pair(const SeamSide& first, const SeamSide& second, const StitchOptions& options,
                            LoopPairPlan& plan) {
  const std::vector<Vec3>& first_points = first.loop_points[plan.first_loop];
  const std::vector<Vec3>& second_positions = second.part.positions;
  const std::vector<int32_t>& second_loop = second.loops[plan.second_loop].vertices;
  const std::vector<int32_t> reversed(second_loop.rbegin(), second_loop.rend());
  const int32_t n = static_cast<int32_t>(reversed.size()), m = static_cast<int32_t>(first_points.size());
  // Direction check: tangents of the first loop and the reversed second loop must agree on average.
  double agree = 0.0;
  for (int32_t k = 0; k < m; ++k) {
    int32_t nearest = 0;
    double nearest_distance = std::numeric_limits<double>::infinity();
    for (int32_t j = 0; j < n; ++j) {
      const double d = glm::length(first_points[k] - second_positions[reversed[j]]);
      if (d < nearest_distance) nearest_distance = d, nearest = j;
    }
    const Vec3 first_tangent = first_points[(k + 1) % m] - first_points[(k + m - 1) % m];
    const Vec3 second_tangent =
        second_positions[reversed[(nearest + 1) % n]] - second_positions[reversed[(nearest + n - 1) % n]];
    const double first_length = glm::length(first_tangent), second_length = glm::length(second_tangent);
    if (first_length > 0 && second_length > 0)
      agree += glm::dot(first_tangent, second_tangent) / (first_length * second_length);
  }
  if (agree <= 0.0) return "a loop pair runs the same way: the parts are not consistently oriented";
  std::vector<int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int32_t x, int32_t y) {
    return glm::length(first_points[0] - second_positions[reversed[x]]) <
           glm::length(first_points[0] - second_positions[reversed[y]]);
  });
  const int32_t tries = std::min<int32_t>(n, std::max<int32_t>(1, options.start_candidates));
  for (int32_t t = 0; t < tries; ++t) {
    std::vector<Vec3> rotated(n);
    std::vector<int32_t> rotated_vertices(n);
    for (int32_t j = 0; j < n; ++j)
      rotated_vertices[j] = reversed[(order[t] + j) % n], rotated[j] = second_positions[rotated_vertices[j]];
    Alignment alignment = align_loops(first_points, rotated, options.min_split);
    if (alignment.cost < plan.alignment.cost)
      plan.alignment = std::move(alignment), plan.second_vertices = std::move(rotated_vertices);
  }
  if (!std::isfinite(plan.alignment.cost)) return "no alignment of a loop pair";
  return {};
}

//! Where seam event `e` lies on each side, given positions of the first part (`first_x`) and of
//! the second part (`second_x`): a vertex, or the point splitting the other loop's edge.
void seam_event_points(const LoopPairPlan& plan, const CutLoop& first_loop, const SeamEvent& e,
                       const std::vector<Vec3>& first_x, const std::vector<Vec3>& second_x, Vec3& on_first,
                       Vec3& on_second) {
  const int32_t m = static_cast<int32_t>(first_loop.vertices.size());
  const std::vector<int32_t>& second_vertices = plan.second_vertices;
  switch (e.kind) {
    case SeamEvent::pair: on_first = first_x[first_loop.vertices[e.first]], on_second = second_x[second_vertices[e.second]]; break;
    case SeamEvent::first_alone:
      on_first = first_x[first_loop.vertices[e.first]];
      on_second = glm::mix(second_x[second_vertices[e.seg0]], second_x[second_vertices[e.seg1]], e.lambda);
      break;
    case SeamEvent::second_alone:
      on_second = second_x[second_vertices[e.second]];
      on_first = glm::mix(first_x[first_loop.vertices[e.seg0 % m]], first_x[first_loop.vertices[e.seg1 % m]], e.lambda);
      break;
  }
}

//! Eq. 5 deformation of one part with its seam vertices pulled to their targets. With
//! anchor_factor > 0, vertices farther than anchor_factor x `edge` from every seam point stay
//! where they are, so only the band of faces touching a vertex within reach is solved (its outer
//! vertices anchored): the system stays a few rings wide however large the element. Returns #V
//! positions. \throw SolverError from the solve.
std::vector<Vec3> deform_seam_band(const TriMesh& part, const std::vector<VertexConstraint>& seam_constraints,
                                   const std::vector<Vec3>& seam_points, double edge, const StitchOptions& options) {
  DeformationOptions deform;
  deform.mu = options.mu;
  if (options.anchor_factor <= 0.0) return deform_with_vertex_constraints(part, seam_constraints, deform);
  const double reach = options.anchor_factor * edge;
  std::vector<uint8_t> free(part.num_vertices(), 0);
  for (size_t v = 0; v < part.num_vertices(); ++v)
    for (const Vec3& s : seam_points)
      if (glm::length(part.positions[v] - s) <= reach) {
        free[v] = 1;
        break;
      }
  TriMesh band;
  std::vector<int32_t> band_of_part(part.num_vertices(), -1), part_of_band;
  for (const Tri& t : part.triangles) {
    if (!free[t[0]] && !free[t[1]] && !free[t[2]]) continue;
    Tri u;
    for (int k = 0; k < 3; ++k) {
      if (band_of_part[t[k]] < 0) {
        band_of_part[t[k]] = static_cast<int32_t>(part_of_band.size());
        part_of_band.push_back(t[k]);
        band.positions.push_back(part.positions[t[k]]);
      }
      u[k] = band_of_part[t[k]];
    }
    band.triangles.push_back(u);
  }
  std::vector<VertexConstraint> constraints;
  for (const VertexConstraint& c : seam_constraints)
    if (band_of_part[c.vertex] >= 0) constraints.push_back({band_of_part[c.vertex], c.target});
  for (size_t l = 0; l < part_of_band.size(); ++l)
    if (!free[part_of_band[l]]) constraints.push_back({static_cast<int32_t>(l), part.positions[part_of_band[l]]});
  const std::vector<Vec3> moved = deform_with_vertex_constraints(band, constraints, deform);
  std::vector<Vec3> x = part.positions;
  for (size_t l = 0; l < part_of_band.size(); ++l)
    if (free[part_of_band[l]]) x[part_of_band[l]] = moved[l];
  return x;
}

//! The two parts joined on their seam, before the boundary faces are split: first-part vertices,
//! then second-part vertices, seam vertices moved onto the averaged seam.
struct WeldedSeam {
  std::vector<Vec3> positions;                   //!< first part's #V then second part's #V
  std::vector<int32_t> origins;                  //!< likewise, when both parts have them
  std::vector<int32_t> first_ids, second_ids;    //!< part vertex -> id in `positions`
  //! boundary face of a part -> ids inserted on its loop half-edge, in seam order
  std::unordered_map<int32_t, std::vector<int32_t>> first_splits, second_splits;
  std::vector<int32_t> seam_vertices;            //!< ids of every seam point
};

//! Welds the seam: a welded second-side vertex becomes its first-side partner; a point alone is
//! moved to the seam and recorded as a split of the other part's boundary face. Returns an empty
//! string, or why the seam cannot be welded.
std::string weld_seam(const SeamSide& first, const SeamSide& second, const std::vector<LoopPairPlan>& plans,
                      const std::vector<Vec3>& first_x, const std::vector<Vec3>& second_x, WeldedSeam& seam) {
  const int32_t first_count = static_cast<int32_t>(first.part.num_vertices());
  seam.positions = first_x;
  seam.positions.insert(seam.positions.end(), second_x.begin(), second_x.end());
  if (!first.part.origins.empty() && !second.part.origins.empty()) {
    seam.origins = first.part.origins;
    seam.origins.insert(seam.origins.end(), second.part.origins.begin(), second.part.origins.end());
  }
  seam.first_ids.resize(first.part.num_vertices());
  std::iota(seam.first_ids.begin(), seam.first_ids.end(), 0);
  seam.second_ids.resize(second.part.num_vertices());
  for (size_t v = 0; v < seam.second_ids.size(); ++v) seam.second_ids[v] = first_count + static_cast<int32_t>(v);
  for (const LoopPairPlan& plan : plans) {
    const CutLoop& first_loop = first.loops[plan.first_loop];
    const int32_t m = static_cast<int32_t>(first_loop.vertices.size());
    // The second part's boundary half-edge on aligned segment (j-1, j) runs j -> j-1; find its face.
    std::unordered_map<uint64_t, int32_t> second_face;
    const CutLoop& second_loop = second.loops[plan.second_loop];
    for (size_t k = 0; k < second_loop.vertices.size(); ++k)
      second_face[directed_edge_key(second_loop.vertices[k], second_loop.vertices[(k + 1) % second_loop.vertices.size()])] =
          second_loop.faces[k];
    for (const SeamEvent& e : plan.alignment.events) {
      Vec3 on_first, on_second;
      seam_event_points(plan, first_loop, e, first_x, second_x, on_first, on_second);
      const Vec3 s = 0.5 * (on_first + on_second);
      switch (e.kind) {
        case SeamEvent::pair:
          seam.positions[first_loop.vertices[e.first]] = s;
          seam.second_ids[plan.second_vertices[e.second]] = first_loop.vertices[e.first];
          seam.seam_vertices.push_back(first_loop.vertices[e.first]);
          break;
        case SeamEvent::first_alone: {
          seam.positions[first_loop.vertices[e.first]] = s;
          const auto it = second_face.find(directed_edge_key(plan.second_vertices[e.seg1], plan.second_vertices[e.seg0]));
          if (it == second_face.end()) return "internal: seam edge not on part b's loop";
          seam.second_splits[it->second].push_back(first_loop.vertices[e.first]);
          seam.seam_vertices.push_back(first_loop.vertices[e.first]);
          break;
        }
        case SeamEvent::second_alone: {
          const int32_t id = first_count + plan.second_vertices[e.second];
          seam.positions[id] = s;
          seam.first_splits[first_loop.faces[e.seg0 % m]].push_back(id);
          seam.seam_vertices.push_back(id);
          break;
        }
      }
    }
  }
  return {};
}

//! Triangles of the stitched element before compaction.
struct SplitFaces {
  std::vector<Tri> triangles;                    //!< first part's faces, then second part's
  size_t from_first = 0;                         //!< how many come from the first part
  std::vector<std::pair<Tri, Vec3>> fan_faces;   //!< each split face with the normal it replaces
};

//! Emits every face of both parts in welded ids, splitting each boundary face that a seam point
//! falls on into a fan that keeps its winding (v0 -> v1 its loop half-edge, c opposite, the
//! inserted points running from v0 to v1; the second part's run the other way). Returns an empty
//! string, or why: a face carrying two loop edges would need a two-sided split (tidy_cut removes
//! such ears).
std::string split_fans(const SeamSide& first, const SeamSide& second, const std::vector<Vec3>& first_x,
                       const std::vector<Vec3>& second_x, const WeldedSeam& seam, SplitFaces& out) {
  for (const auto* side : {&first, &second}) {
    const auto& splits = side == &first ? seam.first_splits : seam.second_splits;
    for (const auto& [f, inserted] : splits) {
      int count = 0;
      for (const CutLoop& l : side->loops) count += static_cast<int>(std::count(l.faces.begin(), l.faces.end(), f));
      if (count > 1) return "a seam face has two cut edges";
    }
  }
  auto emit_part = [&](const SeamSide& side, const std::vector<Vec3>& x, const std::vector<int32_t>& ids,
                       const std::unordered_map<int32_t, std::vector<int32_t>>& splits, bool reverse_inserted) {
    // Which slot of a boundary face carries its loop edge.
    std::unordered_map<int32_t, int32_t> loop_slot;
    for (const CutLoop& l : side.loops)
      for (size_t k = 0; k < l.vertices.size(); ++k) {
        const Tri& t = side.part.triangles[l.faces[k]];
        for (int s = 0; s < 3; ++s)
          if (t[s] == l.vertices[k]) loop_slot[l.faces[k]] = s;
      }
    for (size_t f = 0; f < side.part.num_faces(); ++f) {
      const Tri& pt = side.part.triangles[f];
      const Tri t{ids[pt[0]], ids[pt[1]], ids[pt[2]]};
      const auto it = splits.find(static_cast<int32_t>(f));
      if (it == splits.end() || it->second.empty()) {
        out.triangles.push_back(t);
        continue;
      }
      const int32_t slot = loop_slot.at(static_cast<int32_t>(f));
      const Vec3 replaced_normal = glm::cross(x[pt[1]] - x[pt[0]], x[pt[2]] - x[pt[0]]);
      std::vector<int32_t> chain{t[slot]};
      if (reverse_inserted) chain.insert(chain.end(), it->second.rbegin(), it->second.rend());
      else chain.insert(chain.end(), it->second.begin(), it->second.end());
      chain.push_back(t[(slot + 1) % 3]);
      const int32_t apex = t[(slot + 2) % 3];
      for (size_t k = 0; k + 1 < chain.size(); ++k) {
        out.triangles.push_back({chain[k], chain[k + 1], apex});
        out.fan_faces.push_back({out.triangles.back(), replaced_normal});
      }
    }
  };
  emit_part(first, first_x, seam.first_ids, seam.first_splits, false);
  out.from_first = out.triangles.size();
  emit_part(second, second_x, seam.second_ids, seam.second_splits, true);
  return {};
}

//! Why a face of the stitched element crosses another face it shares no vertex with, among the
//! pairs stitching can have changed (seam faces against every face; first-part faces against
//! second-part faces: each part's own faces are as they were), or nullptr when none does.
//! Candidates come from a BoxGrid of cells two edges wide; each is tested exactly
//! (triangles_intersect: touching counts).
const char* seam_intersection(const TriMesh& mesh, const std::vector<uint8_t>& on_seam, size_t from_first, double edge) {
  std::vector<std::array<Vec3, 3>> corners(mesh.num_faces());
  std::vector<std::array<Vec3, 2>> box(mesh.num_faces());
  BoxGrid grid(std::max(2.0 * edge, 1e-12));
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) corners[f][k] = mesh.positions[mesh.triangles[f][k]];
    box[f][0] = glm::min(glm::min(corners[f][0], corners[f][1]), corners[f][2]);
    box[f][1] = glm::max(glm::max(corners[f][0], corners[f][1]), corners[f][2]);
    grid.insert(static_cast<int32_t>(f), box[f][0], box[f][1]);
  }
  std::vector<int32_t> stamp(mesh.num_faces(), -1);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    const bool seam_face = on_seam[t[0]] || on_seam[t[1]] || on_seam[t[2]];
    if (!seam_face && f >= from_first) continue;
    const char* found = nullptr;
    grid.for_each_cell(box[f][0], box[f][1], [&](const std::vector<int32_t>& near) {
      for (int32_t g : near) {
        if (found) return;
        if (g == static_cast<int32_t>(f) || stamp[g] == static_cast<int32_t>(f)) continue;
        stamp[g] = static_cast<int32_t>(f);
        if (!seam_face && static_cast<size_t>(g) < from_first) continue;
        const auto& bg = box[g];
        const auto& bf = box[f];
        if (bg[1].x < bf[0].x || bg[1].y < bf[0].y || bg[1].z < bf[0].z || bg[0].x > bf[1].x || bg[0].y > bf[1].y ||
            bg[0].z > bf[1].z)
          continue;
        const Tri& u = mesh.triangles[g];
        bool shares = false;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) shares = shares || t[a] == u[b];
        if (!shares && triangles_intersect(corners[f][0], corners[f][1], corners[f][2], corners[g][0], corners[g][1],
                                           corners[g][2]))
          found = seam_face ? "a seam face intersects another face" : "the two parts intersect away from the seam";
      }
    });
    if (found) return found;
  }
  return nullptr;
}

//! Checks the stitched element: every face non-degenerate, every fan face oriented like the face
//! it split, one component, an oriented manifold (closed when both inputs were) and, when asked,
//! no new intersection. Returns an empty string, or why the element is refused.
std::string check_seam(const TriMesh& mesh, const std::vector<std::pair<Tri, Vec3>>& fan_faces,
                       const std::vector<uint8_t>& on_seam, size_t from_first, bool closed_inputs, double edge,
                       const StitchOptions& options) {
  for (const Tri& t : mesh.triangles) {
    const Vec3 &p = mesh.positions[t[0]], &q = mesh.positions[t[1]], &r = mesh.positions[t[2]];
    const double area2 = glm::length(glm::cross(q - p, r - p));
    const double longest = std::max({glm::length(q - p), glm::length(r - q), glm::length(p - r)});
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(area2 > 1e-6 * longest * longest))
      return "the seam created a degenerate triangle";
  }
  for (const auto& [t, replaced_normal] : fan_faces) {
    const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    if (glm::dot(n, replaced_normal) <= 0.0) return "a split seam face flipped";
  }
  const SurfaceReport report = inspect_surface(mesh);
  if (report.components != 1) return "the stitched element has " + std::to_string(report.components) + " components";
  if (report.nonmanifold_edges || report.misoriented_edges || report.pinched_vertices || report.degenerate_faces)
    return "the stitched element is not an oriented manifold";
  if (closed_inputs && !report.closed_manifold()) return "the stitched element is not closed";
  if (options.check_intersections)
    if (const char* why = seam_intersection(mesh, on_seam, from_first, edge)) return why;
  return {};
}

}  // namespace

StitchResult stitch_parts(const TriMesh& a, const std::vector<uint8_t>& keep_a, const TriMesh& b,
                          const std::vector<uint8_t>& keep_b, const StitchOptions& options) {
  const auto neighbors_a = face_neighbors(a), neighbors_b = face_neighbors(b);
  std::vector<CutLoop> loops_a, loops_b;
  std::string why;
  if (!cut_loops(a, neighbors_a, keep_a, loops_a, &why)) return refuse("first part: " + why);
  if (!cut_loops(b, neighbors_b, keep_b, loops_b, &why)) return refuse("second part: " + why);
  if (loops_a.empty() || loops_a.size() != loops_b.size())
    return refuse("the parts have " + std::to_string(loops_a.size()) + " and " + std::to_string(loops_b.size()) +
                  " cut loops");
  for (const auto* set : {&loops_a, &loops_b})
    for (const CutLoop& l : *set)
      if (l.vertices.size() < 3) return refuse("a cut loop has fewer than three vertices");
  const bool closed_inputs = inspect_surface(a).closed_oriented() && inspect_surface(b).closed_oriented();

  SeamSide first, second;
  cut_out_side(a, keep_a, std::move(loops_a), first);
  cut_out_side(b, keep_b, std::move(loops_b), second);

  const std::vector<int32_t> partner = pair_loops(first, second);
  if (partner.empty()) return refuse("the cut loops do not pair up one-to-one");
  std::vector<LoopPairPlan> plans;
  for (size_t i = 0; i < first.loops.size(); ++i) {
    LoopPairPlan plan;
    plan.first_loop = static_cast<int32_t>(i), plan.second_loop = partner[i];
    why = align_loop_pair(first, second, options, plan);
    if (!why.empty()) return refuse(why);
    plans.push_back(std::move(plan));
  }

  // Eq. 5 targets: each seam vertex goes to the average of its event's two side points.
  std::vector<VertexConstraint> first_targets, second_targets;
  std::vector<Vec3> seam_points;
  for (const LoopPairPlan& plan : plans)
    for (const SeamEvent& e : plan.alignment.events) {
      Vec3 on_first, on_second;
      seam_event_points(plan, first.loops[plan.first_loop], e, first.part.positions, second.part.positions, on_first,
                        on_second);
      const Vec3 target = 0.5 * (on_first + on_second);
      if (e.kind != SeamEvent::second_alone) first_targets.push_back({first.loops[plan.first_loop].vertices[e.first], target});
      if (e.kind != SeamEvent::first_alone) second_targets.push_back({plan.second_vertices[e.second], target});
      seam_points.push_back(target);
    }
  const double edge = std::max(mean_edge_length(first.part), mean_edge_length(second.part));
  const std::vector<Vec3> first_x = deform_seam_band(first.part, first_targets, seam_points, edge, options);
  const std::vector<Vec3> second_x = deform_seam_band(second.part, second_targets, seam_points, edge, options);

  WeldedSeam seam;
  why = weld_seam(first, second, plans, first_x, second_x, seam);
  if (!why.empty()) return refuse(why);
  SplitFaces faces;
  why = split_fans(first, second, first_x, second_x, seam, faces);
  if (!why.empty()) return refuse(why);

  // Compact: drop second-part vertices welded away.
  std::vector<int32_t> compact_id(seam.positions.size(), -1);
  TriMesh result;
  for (Tri& t : faces.triangles)
    for (int32_t& v : t) {
      if (compact_id[v] < 0) {
        compact_id[v] = static_cast<int32_t>(result.positions.size());
        result.positions.push_back(seam.positions[v]);
        if (!seam.origins.empty()) result.origins.push_back(seam.origins[v]);
      }
      v = compact_id[v];
    }
  result.triangles = std::move(faces.triangles);
  for (auto& [t, replaced_normal] : faces.fan_faces)
    for (int32_t& v : t) v = compact_id[v];
  std::vector<uint8_t> on_seam(result.num_vertices(), 0);
  for (int32_t v : seam.seam_vertices) on_seam[compact_id[v]] = 1;

  why = check_seam(result, faces.fan_faces, on_seam, faces.from_first, closed_inputs, edge, options);
  if (!why.empty()) return refuse(why);
  StitchResult ok;
  ok.ok = true;
  ok.mesh = std::move(result);
  ok.loop_pairs = static_cast<int32_t>(plans.size());
  return ok;
}

}  // namespace meshquilt
