#include "quilt/element_merging.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "error.h"
#include "quilt/graph_cut.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

Vec3 centroid(const TriMesh& m, size_t f) {
  const Tri& t = m.triangles[f];
  return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0;
}

std::vector<uint8_t> faces_inside(const TriMesh& m, const std::function<bool(const Vec3&)>& in_overlap) {
  std::vector<uint8_t> inside(m.num_faces());
  for (size_t f = 0; f < m.num_faces(); ++f) inside[f] = in_overlap(centroid(m, f)) ? 1 : 0;
  return inside;
}

std::vector<std::vector<int32_t>> faces_around_vertices(const TriMesh& m) {
  std::vector<std::vector<int32_t>> around(m.num_vertices());
  for (size_t f = 0; f < m.num_faces(); ++f)
    for (int32_t v : m.triangles[f]) around[v].push_back(static_cast<int32_t>(f));
  return around;
}

double point_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

//! Distance to a set of segments, exact up to `cap` and reported as `cap` beyond: a hash grid of
//! cell size `cap` holds each segment in every cell its box grown by `cap` touches, so the cell
//! of a query point lists every segment that can be within `cap` of it.
class SegmentDistance {
 public:
  SegmentDistance(std::vector<std::array<Vec3, 2>> segments, double cap) : segments_(std::move(segments)), cap_(cap) {
    for (size_t s = 0; s < segments_.size(); ++s) {
      const Vec3 lo = glm::min(segments_[s][0], segments_[s][1]) - cap_, hi = glm::max(segments_[s][0], segments_[s][1]) + cap_;
      for (int64_t i = cell(lo.x); i <= cell(hi.x); ++i)
        for (int64_t j = cell(lo.y); j <= cell(hi.y); ++j)
          for (int64_t k = cell(lo.z); k <= cell(hi.z); ++k) grid_[key(i, j, k)].push_back(static_cast<int32_t>(s));
    }
  }
  double operator()(const Vec3& p) const {
    const auto it = grid_.find(key(cell(p.x), cell(p.y), cell(p.z)));
    double best = cap_;
    if (it != grid_.end())
      for (int32_t s : it->second) best = std::min(best, point_segment(p, segments_[s][0], segments_[s][1]));
    return best;
  }
  bool empty() const { return segments_.empty(); }

 private:
  int64_t cell(double x) const { return static_cast<int64_t>(std::floor(x / cap_)); }
  static uint64_t key(int64_t i, int64_t j, int64_t k) {
    return static_cast<uint64_t>((i * 73856093) ^ (j * 19349663) ^ (k * 83492791));
  }
  std::vector<std::array<Vec3, 2>> segments_;
  double cap_;
  std::unordered_map<uint64_t, std::vector<int32_t>> grid_;
};

//! Faces within `radius` (along the dual graph, centroid to centroid) of a seed face.
std::vector<uint8_t> grow(const TriMesh& m, const std::vector<std::array<int32_t, 3>>& nb,
                          const std::vector<uint8_t>& seeds, double radius) {
  std::vector<double> dist(m.num_faces(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (size_t f = 0; f < m.num_faces(); ++f)
    if (seeds[f]) dist[f] = 0.0, queue.push({0.0, static_cast<int32_t>(f)});
  while (!queue.empty()) {
    const auto [d, f] = queue.top();
    queue.pop();
    if (d > dist[f]) continue;
    for (int32_t g : nb[f]) {
      if (g < 0) continue;
      const double dg = d + glm::length(centroid(m, f) - centroid(m, g));
      if (dg <= radius && dg < dist[g]) dist[g] = dg, queue.push({dg, g});
    }
  }
  std::vector<uint8_t> within(m.num_faces());
  for (size_t f = 0; f < m.num_faces(); ++f) within[f] = dist[f] <= radius;
  return within;
}

//! The faces of `region` whose connected part of the region (across edges) has a face outside the
//! overlap.
std::vector<uint8_t> reaching_outside(const TriMesh& m, const std::vector<std::array<int32_t, 3>>& nb,
                                      const std::vector<uint8_t>& region, const std::vector<uint8_t>& inside) {
  std::vector<uint8_t> reach(m.num_faces(), 0);
  std::vector<int32_t> stack;
  for (size_t f = 0; f < m.num_faces(); ++f)
    if (region[f] && !inside[f] && !reach[f]) reach[f] = 1, stack.push_back(static_cast<int32_t>(f));
  while (!stack.empty()) {
    const int32_t f = stack.back();
    stack.pop_back();
    for (int32_t g : nb[f])
      if (g >= 0 && region[g] && !reach[g]) reach[g] = 1, stack.push_back(g);
  }
  return reach;
}

//! The dual graph of a mesh with Eq. 7 weights, `dist(v)` standing for Dist(v, C_other).
CutGraph dual_graph(const TriMesh& m, const std::vector<std::array<int32_t, 3>>& nb,
                    const std::vector<double>& dist) {
  CutGraph g;
  g.num_nodes = static_cast<int32_t>(m.num_faces());
  g.source_caps.assign(m.num_faces(), 0.0);
  g.sink_caps.assign(m.num_faces(), 0.0);
  for (size_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t h = nb[f][k];
      if (h <= static_cast<int32_t>(f)) continue;  // each dual edge once; boundary/non-manifold skipped
      const int32_t vi = m.triangles[f][k], vj = m.triangles[f][(k + 1) % 3];
      g.edges.push_back({static_cast<int32_t>(f), h});
      g.weights.push_back((1.0 + glm::length(m.positions[vi] - m.positions[vj])) * (1.0 + dist[vi] + dist[vj]));
    }
  return g;
}

MergeResult whole(const TriMesh& m, MergeOutcome outcome, std::string why = {}) {
  MergeResult r;
  r.outcome = outcome;
  r.element.positions = m.positions;
  r.element.triangles = m.triangles;
  r.fallback = std::move(why);
  return r;
}

size_t count_set(const std::vector<uint8_t>& flags) { return static_cast<size_t>(std::count(flags.begin(), flags.end(), 1)); }

}  // namespace

MergeResult merge_elements(const TriMesh& out_element, const TriMesh& in_element,
                           const std::function<bool(const Vec3&)>& in_overlap, const MergeOptions& options) {
  const TriMesh& co = out_element;
  const TriMesh& ci = in_element;
  if (co.num_faces() == 0) return whole(ci, MergeOutcome::kept_in);
  if (ci.num_faces() == 0) return whole(co, MergeOutcome::kept_out);
  const std::vector<uint8_t> inside_out = faces_inside(co, in_overlap);
  const std::vector<uint8_t> inside_in = faces_inside(ci, in_overlap);
  const size_t outside_out = co.num_faces() - count_set(inside_out);
  const size_t outside_in = ci.num_faces() - count_set(inside_in);
  if (outside_out == 0) return whole(ci, MergeOutcome::kept_in);
  if (outside_in == 0) return whole(co, MergeOutcome::kept_out);

  // When no clean stitch exists the more complete element survives whole, the other is dropped.
  auto fall_back = [&](std::string why) {
    const bool keep_in = outside_in > outside_out || (outside_in == outside_out && ci.num_faces() > co.num_faces());
    return keep_in ? whole(ci, MergeOutcome::kept_in, std::move(why)) : whole(co, MergeOutcome::kept_out, std::move(why));
  };

  const double edge = std::max(mean_edge_length(co), mean_edge_length(ci));
  const double cover = options.coverage_factor * edge;
  const FaceBvh bvh_out(co), bvh_in(ci);
  const auto nb_out = face_neighbors(co), nb_in = face_neighbors(ci);

  // --- Cut of the output element (the paper's rules). ---
  std::vector<ClosestPoint> out_to_in(co.num_vertices());
  std::vector<double> dist_out(co.num_vertices());
  for (size_t v = 0; v < co.num_vertices(); ++v) {
    out_to_in[v] = bvh_in.closest_point(co.positions[v]);
    dist_out[v] = out_to_in[v].distance;
  }
  std::vector<ClosestPoint> in_face_to_out(ci.num_faces());
  std::vector<uint8_t> uncovered_in(ci.num_faces());
  for (size_t f = 0; f < ci.num_faces(); ++f) {
    in_face_to_out[f] = bvh_out.closest_point(centroid(ci, f));
    uncovered_in[f] = in_face_to_out[f].distance > cover;
  }
  // "A face adjacent to f_in with no corresponding vertex in C_out": with different tessellations
  // many faces receive no closest-vertex at all, so correspondence is read as coverage (distance)
  // and adjacency as a band of frontier_factor coverage distances around uncovered faces. Only
  // uncovered regions that reach outside the overlap count: those are where the input continues
  // beyond the output. An uncovered island inside the overlap (the input's end cap sunk inside
  // the output's tube) is where the input ends, and must not push the output's cut away.
  const std::vector<uint8_t> frontier_in =
      grow(ci, nb_in, reaching_outside(ci, nb_in, uncovered_in, inside_in), options.frontier_factor * cover);

  // The mirror image of that rule: where the input ends inside the overlap, the output must stay,
  // or the input could not be cut to meet it there. Output faces near the output's own exclusive
  // region (uncovered by the input, reaching outside the overlap) are kept unless a SINK rule
  // claims them.
  std::vector<uint8_t> uncovered_out(co.num_faces());
  for (size_t f = 0; f < co.num_faces(); ++f) uncovered_out[f] = bvh_in.closest_point(centroid(co, f)).distance > cover;
  // Its reach adds two seam margins, so that the input extends past the output's seam far enough
  // to be cut there itself.
  const double margin = options.seam_margin_factor * edge;
  const std::vector<uint8_t> keep_zone_out = grow(co, nb_out, reaching_outside(co, nb_out, uncovered_out, inside_out),
                                                  options.frontier_factor * cover + 2.0 * margin);

  CutGraph g_out = dual_graph(co, nb_out, dist_out);
  for (size_t f = 0; f < co.num_faces(); ++f)
    if (!inside_out[f]) g_out.source_caps[f] = kInfiniteCapacity;
  const auto around_out = faces_around_vertices(co);
  for (size_t v = 0; v < co.num_vertices(); ++v) {
    const ClosestPoint& cp = out_to_in[v];
    // Only where the input is actually present can it replace the output; deleting output far
    // from the input would open a gap no seam can close.
    if (cp.face < 0 || cp.distance > cover) continue;
    if (inside_in[cp.face] && !frontier_in[cp.face]) continue;
    // SOURCE wins a conflict: the output outside the overlap is never deleted.
    for (int32_t f : around_out[v])
      if (inside_out[f]) g_out.sink_caps[f] = kInfiniteCapacity;
  }
  for (size_t f = 0; f < co.num_faces(); ++f)
    if (keep_zone_out[f] && g_out.sink_caps[f] == 0.0) g_out.source_caps[f] = kInfiniteCapacity;
  // The paper's SINK rule alone can yield only small islands (a few faces at the border of the
  // overlap where both elements coincide, as with interlinked rings); the cheapest cut then
  // punches a small hole around them instead of handing the overlap to the input. The input
  // replaces the output in the overlap (as when the output lies wholly inside it), so covered
  // output faces deep inside the overlap (depth_factor coverage distances from the output's faces
  // outside it, along the surface) are SINK-linked too, below the keep rule above.
  std::vector<uint8_t> out_faces_outside(co.num_faces());
  for (size_t f = 0; f < co.num_faces(); ++f) out_faces_outside[f] = !inside_out[f];
  const std::vector<uint8_t> shallow_out = grow(co, nb_out, out_faces_outside, options.depth_factor * cover);
  for (size_t f = 0; f < co.num_faces(); ++f)
    if (!shallow_out[f] && !keep_zone_out[f] && !uncovered_out[f]) g_out.sink_caps[f] = kInfiniteCapacity;
  std::vector<uint8_t> keep_out = minimum_cut(g_out).source_side;
  tidy_cut(co, nb_out, keep_out);
  const size_t kept_out_faces = count_set(keep_out);
  if (kept_out_faces == 0) return fall_back("the output element's cut kept nothing");

  std::vector<CutLoop> loops_out;
  std::string why;
  if (!cut_loops(co, nb_out, keep_out, loops_out, &why)) return fall_back("output cut: " + why);
  std::vector<std::array<Vec3, 2>> seam;
  for (const CutLoop& l : loops_out)
    for (size_t k = 0; k < l.vertices.size(); ++k)
      seam.push_back({co.positions[l.vertices[k]], co.positions[l.vertices[(k + 1) % l.vertices.size()]]});

  // --- Cut of the input element, complementary to the output's. ---
  // Two independent cuts by the paper's rules need not meet: each may keep geometry the other
  // also keeps (a doubled wall) or both may delete the same stretch (a gap), and the seams can
  // lie far apart. So the input's cut is derived from the output's: input faces nearest kept
  // output faces are deleted, those nearest deleted output faces are kept, and only a margin
  // around the output's cut loops is left to the minimum cut, whose Eq. 7 weights measure the
  // distance to those loops, so both seams run side by side.
  // Beyond a few margins the distance only has to say "far": capped there.
  const SegmentDistance to_loops(seam, 4.0 * margin);
  std::vector<double> dist_in(ci.num_vertices());
  for (size_t v = 0; v < ci.num_vertices(); ++v)
    dist_in[v] = seam.empty() ? bvh_out.closest_point(ci.positions[v]).distance : to_loops(ci.positions[v]);
  CutGraph g_in = dual_graph(ci, nb_in, dist_in);
  std::vector<double> to_seam(ci.num_faces(), std::numeric_limits<double>::infinity());
  if (!seam.empty())
    for (size_t f = 0; f < ci.num_faces(); ++f) to_seam[f] = to_loops(centroid(ci, f));
  // The margin is tried wide first (a smooth cut of its own), then narrower: when the input reaches
  // only a little past the output's seam, a wide margin can swallow every face that must be
  // deleted, and a wide free band may join two nearby seams into one loop. At margin zero the
  // input's cut is the exact complement of the output's, whose loops then pair one-to-one.
  std::string failure = "the input element was never cut";
  for (double scale : {1.0, 0.5, 0.0}) {
    std::fill(g_in.source_caps.begin(), g_in.source_caps.end(), 0.0);
    std::fill(g_in.sink_caps.begin(), g_in.sink_caps.end(), 0.0);
    bool any_sink = false;
    for (size_t f = 0; f < ci.num_faces(); ++f) {
      const ClosestPoint& cp = in_face_to_out[f];
      if (uncovered_in[f]) {
        // The input alone is here: outside the overlap it must stay; inside, the cut decides
        // (an end cap sunk inside the output's tube is then dropped with its surroundings).
        if (!inside_in[f]) g_in.source_caps[f] = kInfiniteCapacity;
        continue;
      }
      if (to_seam[f] <= scale * margin) continue;
      (keep_out[cp.face] ? g_in.sink_caps[f] : g_in.source_caps[f]) = kInfiniteCapacity;
      any_sink = any_sink || keep_out[cp.face];
    }
    if (!any_sink && scale > 0.0) continue;
    std::vector<uint8_t> keep_in = minimum_cut(g_in).source_side;
    tidy_cut(ci, nb_in, keep_in);
    const size_t kept_in_faces = count_set(keep_in);
    if (kept_in_faces == 0) {
      if (kept_out_faces == co.num_faces()) return whole(co, MergeOutcome::kept_out);
      failure = "the input element's cut kept nothing to replace the deleted output";
      continue;
    }
    if (kept_out_faces == co.num_faces()) return fall_back("the output element was not cut but the input keeps faces");
    if (kept_in_faces == ci.num_faces()) {
      failure = "the input element was not cut";
      continue;
    }
    // A failed seam solve is one more reason to keep an element whole, not to stop the synthesis.
    StitchResult stitched;
    try {
      stitched = stitch_parts(co, keep_out, ci, keep_in, options.stitch);
    } catch (const SolverError& e) {
      stitched.failure = std::string("seam deformation: ") + e.what();
    }
    if (!stitched.ok) {
      failure = stitched.failure;
      continue;
    }
    MergeResult r;
    r.outcome = MergeOutcome::stitched;
    r.element = std::move(stitched.mesh);
    r.seam_loops = stitched.loop_pairs;
    return r;
  }
  return fall_back(failure);
}

}  // namespace meshquilt
