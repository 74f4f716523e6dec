#include "quilt/merging/element_merging.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "quilt/merging/graph_cut.h"
#include "quilt/merging/stitching.h"
#include "spatial/box_grid.h"
#include "spatial/face_bvh.h"
#include "spatial/segment_distance.h"

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

//! Distance to a set of segments, exact up to `cap` and reported as `cap` beyond: a grid of cell
//! size `cap` holds each segment in every cell its box grown by `cap` touches, so the cell of a
//! query point lists every segment that can be within `cap` of it.
class SegmentDistance {
 public:
  SegmentDistance(std::vector<std::array<Vec3, 2>> segments, double cap)
      : segments_(std::move(segments)), cap_(cap), grid_(cap) {
    for (size_t s = 0; s < segments_.size(); ++s) {
      const Vec3 lo = glm::min(segments_[s][0], segments_[s][1]) - cap_, hi = glm::max(segments_[s][0], segments_[s][1]) + cap_;
      grid_.insert(static_cast<int32_t>(s), lo, hi);
    }
  }
  double operator()(const Vec3& p) const {
    double best = cap_;
    if (const std::vector<int32_t>* near = grid_.items_at(p))
      for (int32_t s : *near) best = std::min(best, point_segment_distance(p, segments_[s][0], segments_[s][1]));
    return best;
  }
  bool empty() const { return segments_.empty(); }

 private:
  std::vector<std::array<Vec3, 2>> segments_;
  double cap_;
  BoxGrid grid_;
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
  r.element.origins = m.origins;
  r.fallback = std::move(why);
  return r;
}

size_t count_set(const std::vector<uint8_t>& flags) { return static_cast<size_t>(std::count(flags.begin(), flags.end(), 1)); }

//! What both cuts of a related pair read: the two elements, which of their faces lie in the
//! overlap, and how each covers the other.
struct MergeContext {
  MergeContext(const TriMesh& out_element, const TriMesh& in_element, const std::function<bool(const Vec3&)>& in_overlap,
               const MergeOptions& options)
      : out(out_element),
        in(in_element),
        out_inside(faces_inside(out, in_overlap)),
        in_inside(faces_inside(in, in_overlap)),
        edge(std::max(mean_edge_length(out), mean_edge_length(in))),
        cover(options.coverage_factor * edge),
        margin(options.seam_margin_factor * edge) {}

  const TriMesh& out;                //!< C_out, the output element
  const TriMesh& in;                 //!< C_in, the input element
  std::vector<uint8_t> out_inside;   //!< #F of out: centroid in the overlap
  std::vector<uint8_t> in_inside;    //!< #F of in: centroid in the overlap
  double edge;                       //!< larger mean edge length of the two
  double cover;                      //!< coverage distance
  double margin;                     //!< seam margin
};

//! Infinite terminal links of one cut, per face: SOURCE (kept) and SINK (deleted).
struct TerminalLinks {
  std::vector<uint8_t> source, sink;
};

//! Coverage of the output element by the input, and of the input's faces by the output, from the
//! two elements' BVHs.
struct Coverage {
  std::vector<ClosestPoint> out_vertex_to_in;  //!< #V of out: closest input point
  std::vector<double> out_vertex_distance;     //!< #V of out: Dist(v, C_in), Eq. 7
  std::vector<ClosestPoint> in_face_to_out;    //!< #F of in: closest output point to the centroid
  std::vector<uint8_t> in_uncovered;           //!< #F of in: farther than `cover` from the output
  std::vector<uint8_t> out_uncovered;          //!< #F of out: farther than `cover` from the input
};

Coverage measure_coverage(const MergeContext& pair, const FaceBvh& out_bvh, const FaceBvh& in_bvh) {
  Coverage c;
  c.out_vertex_to_in.resize(pair.out.num_vertices());
  c.out_vertex_distance.resize(pair.out.num_vertices());
  for (size_t v = 0; v < pair.out.num_vertices(); ++v) {
    c.out_vertex_to_in[v] = in_bvh.closest_point(pair.out.positions[v]);
    c.out_vertex_distance[v] = c.out_vertex_to_in[v].distance;
  }
  c.in_face_to_out.resize(pair.in.num_faces());
  c.in_uncovered.resize(pair.in.num_faces());
  for (size_t f = 0; f < pair.in.num_faces(); ++f) {
    c.in_face_to_out[f] = out_bvh.closest_point(centroid(pair.in, f));
    c.in_uncovered[f] = c.in_face_to_out[f].distance > pair.cover;
  }
  c.out_uncovered.resize(pair.out.num_faces());
  for (size_t f = 0; f < pair.out.num_faces(); ++f)
    c.out_uncovered[f] = in_bvh.closest_point(centroid(pair.out, f)).distance > pair.cover;
  return c;
}

//! The paper's SOURCE rule: output faces outside the overlap are kept.
std::vector<uint8_t> paper_output_source(const MergeContext& pair) {
  std::vector<uint8_t> source(pair.out.num_faces());
  for (size_t f = 0; f < pair.out.num_faces(); ++f) source[f] = !pair.out_inside[f];
  return source;
}

//! The paper's SINK rule: output faces in the overlap around a vertex whose corresponding input
//! face lies outside the overlap or is adjacent to an input face with no corresponding output
//! vertex. "Corresponding" is read as coverage (within `cover`: with different tessellations many
//! faces receive no closest vertex at all) and "adjacent" as a band of frontier_factor coverage
//! distances around uncovered input faces that reach outside the overlap: those are where the
//! input continues beyond the output. An uncovered island inside the overlap (the input's end cap
//! sunk inside the output's tube) is where the input ends, and must not push the output's cut
//! away. Only faces in the overlap: SOURCE wins a conflict.
std::vector<uint8_t> paper_output_sink(const MergeContext& pair, const Coverage& coverage,
                                       const std::vector<std::array<int32_t, 3>>& in_neighbors,
                                       const MergeOptions& options) {
  const std::vector<uint8_t> in_frontier =
      grow(pair.in, in_neighbors, reaching_outside(pair.in, in_neighbors, coverage.in_uncovered, pair.in_inside),
           options.frontier_factor * pair.cover);
  std::vector<uint8_t> sink(pair.out.num_faces(), 0);
  const auto around = faces_around_vertices(pair.out);
  for (size_t v = 0; v < pair.out.num_vertices(); ++v) {
    const ClosestPoint& cp = coverage.out_vertex_to_in[v];
    // Only where the input is actually present can it replace the output; deleting output far
    // from the input would open a gap no seam can close.
    if (cp.face < 0 || cp.distance > pair.cover) continue;
    if (pair.in_inside[cp.face] && !in_frontier[cp.face]) continue;
    for (int32_t f : around[v])
      if (pair.out_inside[f]) sink[f] = 1;
  }
  return sink;
}

//! Our SOURCE rule, the mirror image of the paper's SINK rule: where the input ends inside the
//! overlap the output must stay, or the input could not be cut to meet it there. Output faces
//! near the output's own exclusive region (uncovered by the input, reaching outside the overlap)
//! are kept unless the paper's SINK rule claims them. The reach adds two seam margins, so that
//! the input extends past the output's seam far enough to be cut there itself.
std::vector<uint8_t> output_keep_zone(const MergeContext& pair, const Coverage& coverage,
                                      const std::vector<std::array<int32_t, 3>>& out_neighbors,
                                      const MergeOptions& options) {
  return grow(pair.out, out_neighbors, reaching_outside(pair.out, out_neighbors, coverage.out_uncovered, pair.out_inside),
              options.frontier_factor * pair.cover + 2.0 * pair.margin);
}

//! Our SINK rule: the paper's SINK rule alone can yield only small islands (a few faces at the
//! border of the overlap where both elements coincide, as with interlinked rings); the cheapest
//! cut then punches a small hole around them instead of handing the overlap to the input. The
//! input replaces the output in the overlap (as when the output lies wholly inside it), so covered
//! output faces deep inside the overlap (depth_factor coverage distances from the output's faces
//! outside it, along the surface) are deleted, unless the keep zone holds them.
std::vector<uint8_t> output_deep_overlap(const MergeContext& pair, const Coverage& coverage,
                                         const std::vector<std::array<int32_t, 3>>& out_neighbors,
                                         const std::vector<uint8_t>& keep_zone, const MergeOptions& options) {
  std::vector<uint8_t> outside(pair.out.num_faces());
  for (size_t f = 0; f < pair.out.num_faces(); ++f) outside[f] = !pair.out_inside[f];
  const std::vector<uint8_t> shallow = grow(pair.out, out_neighbors, outside, options.depth_factor * pair.cover);
  std::vector<uint8_t> deep(pair.out.num_faces());
  for (size_t f = 0; f < pair.out.num_faces(); ++f) deep[f] = !shallow[f] && !keep_zone[f] && !coverage.out_uncovered[f];
  return deep;
}

//! Terminal links of the output element's cut, the paper's rules and ours side by side, in
//! precedence: SOURCE = paper SOURCE, or our keep zone where the paper's SINK does not claim the
//! face; SINK = paper SINK (only in the overlap, so the paper's SOURCE wins), or deep overlap
//! (never in the keep zone, never outside the overlap).
TerminalLinks output_terminal_links(const MergeContext& pair, const Coverage& coverage,
                                    const std::vector<std::array<int32_t, 3>>& out_neighbors,
                                    const std::vector<std::array<int32_t, 3>>& in_neighbors,
                                    const MergeOptions& options) {
  const std::vector<uint8_t> paper_source = paper_output_source(pair);
  const std::vector<uint8_t> paper_sink = paper_output_sink(pair, coverage, in_neighbors, options);
  const std::vector<uint8_t> keep_zone = output_keep_zone(pair, coverage, out_neighbors, options);
  const std::vector<uint8_t> deep = output_deep_overlap(pair, coverage, out_neighbors, keep_zone, options);
  TerminalLinks links;
  links.source.resize(pair.out.num_faces());
  links.sink.resize(pair.out.num_faces());
  for (size_t f = 0; f < pair.out.num_faces(); ++f) {
    links.source[f] = paper_source[f] || (keep_zone[f] && !paper_sink[f]);
    links.sink[f] = paper_sink[f] || deep[f];
  }
  return links;
}

//! Terminal links of the input element's cut, complementary to the output's cut `keep_out`. Two
//! independent cuts by the paper's rules need not meet: each may keep geometry the other also
//! keeps (a doubled wall) or both may delete the same stretch (a gap). So input faces nearest
//! kept output faces are SINK, those nearest deleted output faces SOURCE; input faces the output
//! does not cover are SOURCE outside the overlap and free inside it (an end cap sunk inside the
//! output's tube is then dropped with its surroundings); faces within `free_margin` of the
//! output's cut loops (`to_seam`, #F) are free, so the cut follows the loops.
TerminalLinks input_terminal_links(const MergeContext& pair, const Coverage& coverage, const std::vector<uint8_t>& keep_out,
                                   const std::vector<double>& to_seam, double free_margin) {
  TerminalLinks links;
  links.source.assign(pair.in.num_faces(), 0);
  links.sink.assign(pair.in.num_faces(), 0);
  for (size_t f = 0; f < pair.in.num_faces(); ++f) {
    if (coverage.in_uncovered[f]) {
      if (!pair.in_inside[f]) links.source[f] = 1;
      continue;
    }
    if (to_seam[f] <= free_margin) continue;
    (keep_out[coverage.in_face_to_out[f].face] ? links.sink[f] : links.source[f]) = 1;
  }
  return links;
}

//! Infinite capacities on a cut graph's terminal links.
void link_terminals(const TerminalLinks& links, CutGraph& graph) {
  for (size_t f = 0; f < links.source.size(); ++f) {
    graph.source_caps[f] = links.source[f] ? kInfiniteCapacity : 0.0;
    graph.sink_caps[f] = links.sink[f] ? kInfiniteCapacity : 0.0;
  }
}

}  // namespace

MergeResult merge_elements(const TriMesh& out_element, const TriMesh& in_element,
                           const std::function<bool(const Vec3&)>& in_overlap, const MergeOptions& options) {
  if (out_element.num_faces() == 0) return whole(in_element, MergeOutcome::kept_in);
  if (in_element.num_faces() == 0) return whole(out_element, MergeOutcome::kept_out);
  const MergeContext pair(out_element, in_element, in_overlap, options);
  const size_t out_outside = out_element.num_faces() - count_set(pair.out_inside);
  const size_t in_outside = in_element.num_faces() - count_set(pair.in_inside);
  if (out_outside == 0) return whole(in_element, MergeOutcome::kept_in);
  if (in_outside == 0) return whole(out_element, MergeOutcome::kept_out);

  // When no clean stitch exists the more complete element survives whole, the other is dropped.
  auto fall_back = [&](std::string why) {
    const bool keep_in = in_outside > out_outside ||
                         (in_outside == out_outside && in_element.num_faces() > out_element.num_faces());
    return keep_in ? whole(in_element, MergeOutcome::kept_in, std::move(why))
                   : whole(out_element, MergeOutcome::kept_out, std::move(why));
  };

  // Two BVHs per merged pair, each queried about once per vertex: the fast build pays, and
  // closest points break ties by face, so answers do not depend on it.
  const FaceBvh out_bvh(out_element, BvhQuality::low), in_bvh(in_element, BvhQuality::low);
  const auto out_neighbors = face_neighbors(out_element), in_neighbors = face_neighbors(in_element);
  const Coverage coverage = measure_coverage(pair, out_bvh, in_bvh);

  // Cut of the output element: Eq. 7 weights with Dist to the input.
  CutGraph out_graph = dual_graph(out_element, out_neighbors, coverage.out_vertex_distance);
  link_terminals(output_terminal_links(pair, coverage, out_neighbors, in_neighbors, options), out_graph);
  std::vector<uint8_t> keep_out = minimum_cut(out_graph).source_side;
  tidy_cut(out_element, out_neighbors, keep_out);
  const size_t kept_out_faces = count_set(keep_out);
  if (kept_out_faces == 0) return fall_back("the output element's cut kept nothing");

  std::vector<CutLoop> out_loops;
  std::string why;
  if (!cut_loops(out_element, out_neighbors, keep_out, out_loops, &why)) return fall_back("output cut: " + why);
  std::vector<std::array<Vec3, 2>> out_seam;
  for (const CutLoop& l : out_loops)
    for (size_t k = 0; k < l.vertices.size(); ++k)
      out_seam.push_back({out_element.positions[l.vertices[k]], out_element.positions[l.vertices[(k + 1) % l.vertices.size()]]});

  // Cut of the input element, complementary to the output's: Eq. 7 weights with the distance to
  // the output's cut loops, so both seams run side by side. Beyond a few margins the distance only
  // has to say "far": capped there.
  const SegmentDistance to_loops(out_seam, 4.0 * pair.margin);
  std::vector<double> in_vertex_distance(in_element.num_vertices());
  for (size_t v = 0; v < in_element.num_vertices(); ++v)
    in_vertex_distance[v] =
        out_seam.empty() ? out_bvh.closest_point(in_element.positions[v]).distance : to_loops(in_element.positions[v]);
  CutGraph in_graph = dual_graph(in_element, in_neighbors, in_vertex_distance);
  std::vector<double> to_seam(in_element.num_faces(), std::numeric_limits<double>::infinity());
  if (!out_seam.empty())
    for (size_t f = 0; f < in_element.num_faces(); ++f) to_seam[f] = to_loops(centroid(in_element, f));
  // The margin is tried wide first (a smooth cut of its own), then narrower: when the input reaches
  // only a little past the output's seam, a wide margin can swallow every face that must be
  // deleted, and a wide free band may join two nearby seams into one loop. At margin zero the
  // input's cut is the exact complement of the output's, whose loops then pair one-to-one.
  std::string failure = "the input element was never cut";
  for (double scale : {1.0, 0.5, 0.0}) {
    const TerminalLinks in_links = input_terminal_links(pair, coverage, keep_out, to_seam, scale * pair.margin);
    if (count_set(in_links.sink) == 0 && scale > 0.0) continue;
    link_terminals(in_links, in_graph);
    std::vector<uint8_t> keep_in = minimum_cut(in_graph).source_side;
    tidy_cut(in_element, in_neighbors, keep_in);
    const size_t kept_in_faces = count_set(keep_in);
    if (kept_in_faces == 0) {
      if (kept_out_faces == out_element.num_faces()) return whole(out_element, MergeOutcome::kept_out);
      failure = "the input element's cut kept nothing to replace the deleted output";
      continue;
    }
    if (kept_out_faces == out_element.num_faces())
      return fall_back("the output element was not cut but the input keeps faces");
    if (kept_in_faces == in_element.num_faces()) {
      failure = "the input element was not cut";
      continue;
    }
    // A failed seam solve is one more reason to keep an element whole, not to stop the synthesis.
    StitchResult stitched;
    try {
      stitched = stitch_parts(out_element, keep_out, in_element, keep_in, options.stitch);
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
