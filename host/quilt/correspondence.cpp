#include "quilt/correspondence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "mesh/measures.h"
#include "spatial/exact_predicates.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

struct Box2 {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void add(const Vec3& p) {
    lo[0] = std::min(lo[0], p.x), lo[1] = std::min(lo[1], p.y);
    hi[0] = std::max(hi[0], p.x), hi[1] = std::max(hi[1], p.y);
  }
  bool empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1]); }
  bool overlaps(const Box2& o) const {
    return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1];
  }
  Box2 intersection(const Box2& o) const {
    Box2 r;
    for (int k = 0; k < 2; ++k) r.lo[k] = std::max(lo[k], o.lo[k]), r.hi[k] = std::min(hi[k], o.hi[k]);
    return r;
  }
};

int orient(const Vec3& a, const Vec3& b, const Vec3& c) { return orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

//! Collinear p lies within the closed segment [a, b] (coordinate ranges are exact for collinear points).
bool within(const Vec3& a, const Vec3& b, const Vec3& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_overlap_2d(const Vec3& p1, const Vec3& p2, const Vec3& q1, const Vec3& q2) {
  const int o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
  const int o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within(p1, p2, q1)) || (o2 == 0 && within(p1, p2, q2)) ||
         (o3 == 0 && within(q1, q2, p1)) || (o4 == 0 && within(q1, q2, p2));
}

//! p in the closed projected triangle (a, b, c); false when the triangle's projection is collinear.
bool point_in_triangle_2d(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int s = orient(a, b, c);
  if (s == 0) return false;
  return orient(a, b, p) * s >= 0 && orient(b, c, p) * s >= 0 && orient(c, a, p) * s >= 0;
}

//! The x-y projection of one element's triangles, with per-triangle boxes.
struct Projection {
  const TriMesh* mesh = nullptr;
  std::vector<Box2> boxes;
  Box2 box;
};

void project(const TriMesh& mesh, Projection& out) {
  out.mesh = &mesh;
  out.boxes.resize(mesh.num_faces());
  out.box = Box2{};
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    Box2 b;
    for (int k = 0; k < 3; ++k) b.add(mesh.positions[mesh.triangles[f][k]]);
    out.boxes[f] = b;
    out.box.lo[0] = std::min(out.box.lo[0], b.lo[0]), out.box.lo[1] = std::min(out.box.lo[1], b.lo[1]);
    out.box.hi[0] = std::max(out.box.hi[0], b.hi[0]), out.box.hi[1] = std::max(out.box.hi[1], b.hi[1]);
  }
}

//! Reused buffers of the grid test, so relation after relation allocates nothing new.
struct OverlapScratch {
  std::vector<int32_t> a_faces, b_faces, cell_start, cell_faces, stamp;
};

bool triangles_overlap(const TriMesh& a, int32_t fa, const TriMesh& b, int32_t fb) {
  const Tri& ta = a.triangles[fa];
  const Tri& tb = b.triangles[fb];
  return projected_triangles_overlap(a.positions[ta[0]], a.positions[ta[1]], a.positions[ta[2]],
                                     b.positions[tb[0]], b.positions[tb[1]], b.positions[tb[2]]);
}

bool projections_overlap(const Projection& a, const Projection& b, OverlapScratch& s) {
  if (a.box.empty() || b.box.empty() || !a.box.overlaps(b.box)) return false;
  const Box2 common = a.box.intersection(b.box);
  s.a_faces.clear();
  s.b_faces.clear();
  for (size_t f = 0; f < a.boxes.size(); ++f)
    if (a.boxes[f].overlaps(common)) s.a_faces.push_back(static_cast<int32_t>(f));
  for (size_t f = 0; f < b.boxes.size(); ++f)
    if (b.boxes[f].overlaps(common)) s.b_faces.push_back(static_cast<int32_t>(f));
  if (s.a_faces.empty() || s.b_faces.empty()) return false;

  // Bin b's faces into a uniform grid over the common box; the cell of a coordinate is a
  // monotone function of it, so two boxes sharing a point share a cell.
  const int g = std::clamp(static_cast<int>(std::ceil(std::sqrt(s.b_faces.size() / 2.0))), 1, 128);
  const double w[2] = {common.hi[0] - common.lo[0], common.hi[1] - common.lo[1]};
  auto cell_of = [&](double x, int k) {
    if (!(w[k] > 0.0)) return 0;
    return std::clamp(static_cast<int>((x - common.lo[k]) / w[k] * g), 0, g - 1);
  };
  auto cell_range = [&](const Box2& box, int range[4]) {
    range[0] = cell_of(box.lo[0], 0), range[1] = cell_of(box.hi[0], 0);
    range[2] = cell_of(box.lo[1], 1), range[3] = cell_of(box.hi[1], 1);
  };
  s.cell_start.assign(static_cast<size_t>(g) * g + 1, 0);
  int range[4];
  for (int32_t f : s.b_faces) {
    cell_range(b.boxes[f], range);
    for (int y = range[2]; y <= range[3]; ++y)
      for (int x = range[0]; x <= range[1]; ++x) ++s.cell_start[y * g + x + 1];
  }
  std::partial_sum(s.cell_start.begin(), s.cell_start.end(), s.cell_start.begin());
  s.cell_faces.resize(s.cell_start.back());
  {
    std::vector<int32_t>& fill = s.stamp;  // used as a cursor per cell here
    fill.assign(s.cell_start.begin(), s.cell_start.end() - 1);
    for (int32_t f : s.b_faces) {
      cell_range(b.boxes[f], range);
      for (int y = range[2]; y <= range[3]; ++y)
        for (int x = range[0]; x <= range[1]; ++x) s.cell_faces[fill[y * g + x]++] = f;
    }
  }
  // stamp[f] = the last a-face f was tested against, so a pair spanning cells is tested once.
  s.stamp.assign(b.boxes.size(), -1);
  for (int32_t fa : s.a_faces) {
    const Box2& box = a.boxes[fa];
    cell_range(box, range);
    for (int y = range[2]; y <= range[3]; ++y)
      for (int x = range[0]; x <= range[1]; ++x)
        for (int32_t k = s.cell_start[y * g + x]; k < s.cell_start[y * g + x + 1]; ++k) {
          const int32_t fb = s.cell_faces[k];
          if (s.stamp[fb] == fa) continue;
          s.stamp[fb] = fa;
          if (box.overlaps(b.boxes[fb]) && triangles_overlap(*a.mesh, fa, *b.mesh, fb)) return true;
        }
  }
  return false;
}

void check_indices(const TriMesh& mesh, const char* side, size_t element) {
  const int32_t nv = static_cast<int32_t>(mesh.num_vertices());
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f])
      if (v < 0 || v >= nv)
        throw InputError(std::string("correspondence: ") + side + " element " + std::to_string(element) + " face " +
                         std::to_string(f) + " has vertex index " + std::to_string(v) + " outside [0, " +
                         std::to_string(nv) + ")");
}

//! All input elements as one mesh for one BVH, with what the prunings need per face and vertex.
struct JoinedInput {
  TriMesh mesh;
  std::vector<int32_t> face_element, face_local;
  std::vector<Vec3> face_normal;  // unit, zero for degenerate faces
  std::vector<FaceSphere> face_sphere;
  // The faces around each vertex in compressed rows: a counting sort, since this is built per
  // patch and sorting every edge was a large share of correspondence.
  std::vector<int32_t> vertex_face_first, vertex_faces;
  std::vector<double> element_longest_edge;  // of each element's faces

  explicit JoinedInput(const std::vector<TriMesh>& elements) : element_longest_edge(elements.size(), 0.0) {
    size_t nv = 0, nf = 0;
    for (const TriMesh& e : elements) nv += e.num_vertices(), nf += e.num_faces();
    mesh.positions.reserve(nv);
    mesh.triangles.reserve(nf);
    face_element.reserve(nf);
    face_local.reserve(nf);
    for (size_t i = 0; i < elements.size(); ++i) {
      const TriMesh& e = elements[i];
      check_indices(e, "input", i);
      const int32_t offset = static_cast<int32_t>(mesh.positions.size());
      mesh.positions.insert(mesh.positions.end(), e.positions.begin(), e.positions.end());
      for (size_t f = 0; f < e.num_faces(); ++f) {
        const Tri& t = e.triangles[f];
        mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        face_element.push_back(static_cast<int32_t>(i));
        face_local.push_back(static_cast<int32_t>(f));
      }
    }
    measure();
    vertex_face_first.assign(mesh.positions.size() + 1, 0);
    for (const Tri& t : mesh.triangles)
      for (int32_t v : t) ++vertex_face_first[v + 1];
    std::partial_sum(vertex_face_first.begin(), vertex_face_first.end(), vertex_face_first.begin());
    vertex_faces.resize(vertex_face_first.back());
    std::vector<int32_t> fill(vertex_face_first.begin(), vertex_face_first.end() - 1);
    for (size_t f = 0; f < nf; ++f)
      for (int32_t v : mesh.triangles[f]) vertex_faces[fill[v]++] = static_cast<int32_t>(f);
  }

  //! A copy with every position moved by `offset`, its measures taken anew from the moved
  //! positions: bit for bit those of the moved elements joined (normals, spheres and lengths
  //! round differently at another position).
  JoinedInput moved(const Vec3& offset) const {
    JoinedInput copy = *this;
    for (Vec3& p : copy.mesh.positions) p += offset;
    copy.measure();
    return copy;
  }

  // What depends on the positions: unit normals, spheres and each element's longest edge.
  void measure() {
    const size_t nf = mesh.num_faces();
    face_normal.resize(nf);
    face_sphere = face_spheres(mesh);
    std::fill(element_longest_edge.begin(), element_longest_edge.end(), 0.0);
    for (size_t f = 0; f < nf; ++f) {
      const Tri& t = mesh.triangles[f];
      const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
      const double len = glm::length(n);
      face_normal[f] = len > 0.0 ? n / len : Vec3(0.0);
      for (int k = 0; k < 3; ++k)
        if (t[k] != t[(k + 1) % 3])
          element_longest_edge[face_element[f]] =
              std::max(element_longest_edge[face_element[f]], glm::length(mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]));
    }
  }

  //! Mean length of the distinct edges with an endpoint at a vertex of face f (pruning (b)).
  double local_mean_edge_length(int32_t f) const {
    const Tri& t = mesh.triangles[f];
    auto in_face = [&](int32_t v) { return v == t[0] || v == t[1] || v == t[2]; };
    double sum = 0.0;
    int count = 0;
    std::vector<int32_t> neighbours;
    for (int k = 0; k < 3; ++k) {
      const int32_t v = t[k];
      if ((k > 0 && v == t[0]) || (k > 1 && v == t[1])) continue;  // repeated index
      // v's distinct neighbours in increasing order (the sum's order does not depend on the faces').
      neighbours.clear();
      for (int32_t e = vertex_face_first[v]; e < vertex_face_first[v + 1]; ++e)
        for (int32_t w : mesh.triangles[vertex_faces[e]])
          if (w != v) neighbours.push_back(w);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      for (int32_t w : neighbours) {
        // An edge between two face vertices is seen from both ends: count it from the lower one.
        if (in_face(w) && w < v) continue;
        sum += glm::length(mesh.positions[v] - mesh.positions[w]);
        ++count;
      }
    }
    return count > 0 ? sum / count : 0.0;
  }
};

//! #V: whether any triangle uses each vertex (a vertex no face uses has no normal to compare).
std::vector<uint8_t> used_vertices(const TriMesh& mesh) {
  std::vector<uint8_t> used(mesh.num_vertices(), 0);
  for (const Tri& t : mesh.triangles)
    for (int32_t v : t) used[v] = 1;
  return used;
}

struct Query {
  int32_t element, vertex;
  Vec3 position, normal;
};

}  // namespace

bool projected_triangles_overlap(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                 const Vec3& b0, const Vec3& b1, const Vec3& b2) {
  const Vec3* a[3] = {&a0, &a1, &a2};
  const Vec3* b[3] = {&b0, &b1, &b2};
  // Closed convex sets meet iff their boundaries cross or one holds a vertex of the other; a
  // collinear projection is the union of its edges, so the edge test covers it.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_overlap_2d(*a[i], *a[(i + 1) % 3], *b[j], *b[(j + 1) % 3])) return true;
  return point_in_triangle_2d(b0, a0, a1, a2) || point_in_triangle_2d(a0, b0, b1, b2);
}

bool projections_overlap(const TriMesh& a, const TriMesh& b) {
  Projection pa, pb;
  project(a, pa);
  project(b, pb);
  OverlapScratch scratch;
  return projections_overlap(pa, pb, scratch);
}

struct SwatchFaces::Impl {
  JoinedInput joined;
  FaceBvh bvh;
  explicit Impl(const std::vector<TriMesh>& elements) : joined(elements), bvh(joined.mesh) {}
};

SwatchFaces::SwatchFaces(const std::vector<TriMesh>& elements) : impl_(std::make_unique<Impl>(elements)) {}
SwatchFaces::~SwatchFaces() = default;

namespace {

Correspondences relate(const std::vector<TriMesh>& out_elements, const std::vector<TriMesh>& in_elements,
                       const std::vector<Query>& queries, const CorrespondenceOptions& options,
                       const JoinedInput& input, const FaceBvh& bvh, const std::vector<int32_t>& input_of,
                       const Vec3& offset);

// The queries, then the search over `faces` (the swatch's elements `sources` moved by
// `translation`) or, without it, over a BVH of in_elements built here.
Correspondences correspond(const std::vector<TriMesh>& out_elements, const std::vector<TriMesh>& in_elements,
                           const std::function<bool(const Vec3&)>& in_overlap, const CorrespondenceOptions& options,
                           const SwatchFaces::Impl* faces, const std::vector<int32_t>& sources,
                           const glm::dvec2& translation) {
  const double lambda = options.lambda;
  if (!(lambda >= 0.0) || !std::isfinite(lambda)) {
    throw InputError("correspondence: lambda = " + std::to_string(lambda) + " must be finite and >= 0",
                     ErrorKind::invalid_option);
  }
  if (!(options.max_distance_factor > 0.0)) {
    throw InputError("correspondence: max_distance_factor = " + std::to_string(options.max_distance_factor) +
                         " must be positive",
                     ErrorKind::invalid_option);
  }
  Correspondences result;

  // Output vertices in the overlap, with their normals (only elements that have some).
  std::vector<Query> queries;
  for (size_t e = 0; e < out_elements.size(); ++e) {
    const TriMesh& mesh = out_elements[e];
    check_indices(mesh, "output", e);
    const std::vector<Vec3> normals = vertex_normals(mesh, Vec3(0.0));
    const std::vector<uint8_t> used = used_vertices(mesh);
    for (size_t v = 0; v < mesh.num_vertices(); ++v) {
      if (!used[v] || !in_overlap(mesh.positions[v])) continue;
      queries.push_back({static_cast<int32_t>(e), static_cast<int32_t>(v), mesh.positions[v], normals[v]});
    }
  }
  if (queries.empty() || in_elements.empty()) return result;

  if (!faces) {
    const JoinedInput joined(in_elements);
    if (joined.mesh.triangles.empty()) return result;
    // Built for every call and queried a few hundred times: Embree's fast build pays (ties go
    // to the lower face either way, so answers are the same).
    const FaceBvh bvh(joined.mesh, BvhQuality::low);
    std::vector<int32_t> identity(in_elements.size());
    std::iota(identity.begin(), identity.end(), 0);
    return relate(out_elements, in_elements, queries, options, joined, bvh, identity, Vec3(0.0));
  }
  std::vector<int32_t> input_of(faces->joined.element_longest_edge.size(), -1);
  for (size_t i = 0; i < sources.size(); ++i) input_of.at(sources[i]) = static_cast<int32_t>(i);
  const Vec3 offset(translation, 0.0);
  return relate(out_elements, in_elements, queries, options, faces->joined.moved(offset), faces->bvh, input_of, offset);
}

Correspondences relate(const std::vector<TriMesh>& out_elements, const std::vector<TriMesh>& in_elements,
                       const std::vector<Query>& queries, const CorrespondenceOptions& options,
                       const JoinedInput& input, const FaceBvh& bvh, const std::vector<int32_t>& input_of,
                       const Vec3& offset) {
  const double lambda = options.lambda;
  Correspondences result;
  // Pruning (b) drops every pair farther than max_distance_factor x the local mean edge, which is
  // at most the inputs' longest edge: a query with no face within `reach` is dropped whatever
  // face minimizes Eq. 1 (the Apple row's points between fruit, a sixth of its queries).
  double longest_edge = 0.0;
  for (size_t e = 0; e < input_of.size(); ++e)
    if (input_of[e] >= 0) longest_edge = std::max(longest_edge, input.element_longest_edge[e]);
  const double reach = options.max_distance_factor * longest_edge * (1.0 + 1e-9);

  // Eq. 1-2 per query. Each chunk builds its cost functions once, around a pointer to the current
  // query, so a query allocates nothing.
  std::vector<ClosestPoint> nearest(queries.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, queries.size(), 32), [&](const tbb::blocked_range<size_t>& r) {
    const Query* current = nullptr;
    // A face of an element that is not an input costs infinity, which never wins (a search
    // without a finite bound yet still measures it).
    const std::function<double(const ClosestPoint&)> cost = [&current, &input, &input_of, lambda](const ClosestPoint& cp) {
      if (input_of[input.face_element[cp.face]] < 0) return std::numeric_limits<double>::infinity();
      return (1.0 + lambda * cp.distance) * (1.0 + glm::length(current->normal - input.face_normal[cp.face]));
    };
    // D >= 1 + lambda Dist: beyond (D_best - 1) / lambda no face can do better. The bound is not
    // seeded: the BVH's near-first traversal already finds a good face early.
    const std::function<double(double)> radius_for = [lambda](double best) {
      return lambda > 0.0 ? (best - 1.0) / lambda : std::numeric_limits<double>::infinity();
    };
    // A face's normal term and its bounding sphere rule most faces out without a closest point.
    // (Also notes whether the face may lie within reach: its sphere's gap is at most its distance.)
    bool near_seen = false;
    const std::function<double(int32_t)> bound = [&current, &input, &input_of, lambda, reach, &near_seen](int32_t f) {
      if (input_of[input.face_element[f]] < 0) return std::numeric_limits<double>::infinity();  // not an input
      const auto& [centre, radius] = input.face_sphere[f];
      const double gap = std::max(glm::length(current->position - centre) - radius, 0.0);
      near_seen = near_seen || gap <= reach;
      return (1.0 + lambda * gap) * (1.0 + glm::length(current->normal - input.face_normal[f]));
    };
    double best = 0.0;
    // A face beyond reach costs more than 1 + lambda x reach: the search starts there, and a face
    // that costs less is the minimum. Where none does, a query whose search met no face that may
    // lie within reach (it meets every face within its radius) has no pair; the others search on.
    // (Without a distance term or without pruning (b) there is no such radius.)
    const bool capped_first = lambda > 0.0 && std::isfinite(reach);
    const double capped = 1.0 + lambda * reach;
    for (size_t q = r.begin(); q != r.end(); ++q) {
      current = &queries[q];
      if (capped_first) {
        near_seen = false;
        nearest[q] = bvh.min_cost_face(current->position, cost, radius_for, &best, capped, bound, -1, offset);
        if (nearest[q].face >= 0 || !near_seen) continue;
      }
      nearest[q] = bvh.min_cost_face(current->position, cost, radius_for, &best,
                                     std::numeric_limits<double>::infinity(), bound, -1, offset);
    }
  });

  // Prunings (a) and (b).
  std::vector<VertexFacePair> candidates;
  candidates.reserve(queries.size());
  for (size_t q = 0; q < queries.size(); ++q) {
    const ClosestPoint& cp = nearest[q];
    if (cp.face < 0) continue;
    if (glm::dot(queries[q].normal, input.face_normal[cp.face]) < 0.0) continue;
    if (cp.distance > options.max_distance_factor * input.local_mean_edge_length(cp.face)) continue;
    VertexFacePair p;
    p.out_element = queries[q].element;
    p.out_vertex = queries[q].vertex;
    p.in_element = input_of[input.face_element[cp.face]];
    p.in_face = input.face_local[cp.face];
    p.closest = cp.point;
    p.barycentric = cp.barycentric;
    p.distance = cp.distance;
    candidates.push_back(p);
  }

  // Relations, then pruning (c) on their projections.
  std::vector<int32_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
    return std::pair(candidates[a].out_element, candidates[a].in_element) <
           std::pair(candidates[b].out_element, candidates[b].in_element);
  });
  std::vector<Projection> out_proj(out_elements.size()), in_proj(in_elements.size());
  OverlapScratch scratch;
  std::vector<uint8_t> keep(candidates.size(), 0);
  std::vector<std::pair<size_t, size_t>> groups;  // [begin, end) into order
  for (size_t begin = 0; begin < order.size();) {
    const VertexFacePair& first = candidates[order[begin]];
    size_t end = begin;
    while (end < order.size() && candidates[order[end]].out_element == first.out_element &&
           candidates[order[end]].in_element == first.in_element)
      ++end;
    const TriMesh& out_mesh = out_elements[first.out_element];
    const TriMesh& in_mesh = in_elements[first.in_element];
    // A paired vertex lying inside its face's projection already proves the overlap (the vertex
    // belongs to an output triangle).
    bool overlap = false;
    for (size_t k = begin; k < end && !overlap; ++k) {
      const VertexFacePair& p = candidates[order[k]];
      const Tri& t = in_mesh.triangles[p.in_face];
      overlap = point_in_triangle_2d(out_mesh.positions[p.out_vertex], in_mesh.positions[t[0]],
                                     in_mesh.positions[t[1]], in_mesh.positions[t[2]]);
    }
    if (!overlap) {
      Projection& po = out_proj[first.out_element];
      Projection& pi = in_proj[first.in_element];
      if (!po.mesh) project(out_mesh, po);
      if (!pi.mesh) project(in_mesh, pi);
      overlap = projections_overlap(po, pi, scratch);
    }
    if (overlap) {
      for (size_t k = begin; k < end; ++k) keep[order[k]] = 1;
      groups.emplace_back(begin, end);
    }
    begin = end;
  }

  std::vector<int32_t> new_index(candidates.size(), -1);
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (!keep[i]) continue;
    new_index[i] = static_cast<int32_t>(result.pairs.size());
    result.pairs.push_back(candidates[i]);
  }
  result.relations.reserve(groups.size());
  for (const auto& [begin, end] : groups) {
    ElementRelation rel;
    rel.out_element = candidates[order[begin]].out_element;
    rel.in_element = candidates[order[begin]].in_element;
    rel.pairs.reserve(end - begin);
    // The stable sort kept candidate order inside a group, and new indices preserve it.
    for (size_t k = begin; k < end; ++k) rel.pairs.push_back(new_index[order[k]]);
    result.relations.push_back(std::move(rel));
  }
  std::sort(result.relations.begin(), result.relations.end(), [](const ElementRelation& a, const ElementRelation& b) {
    if (a.pairs.size() != b.pairs.size()) return a.pairs.size() > b.pairs.size();
    return std::pair(a.out_element, a.in_element) < std::pair(b.out_element, b.in_element);
  });
  return result;
}

}  // namespace

Correspondences find_correspondences(const std::vector<TriMesh>& out_elements,
                                     const std::vector<TriMesh>& in_elements,
                                     const std::function<bool(const Vec3&)>& in_overlap,
                                     const CorrespondenceOptions& options) {
  return correspond(out_elements, in_elements, in_overlap, options, nullptr, {}, glm::dvec2(0.0));
}

Correspondences find_correspondences(const std::vector<TriMesh>& out_elements,
                                     const std::vector<TriMesh>& in_elements, const SwatchFaces& swatch,
                                     const std::vector<int32_t>& sources, const glm::dvec2& translation,
                                     const std::function<bool(const Vec3&)>& in_overlap,
                                     const CorrespondenceOptions& options) {
  if (sources.size() != in_elements.size())
    throw std::invalid_argument("find_correspondences: " + std::to_string(sources.size()) + " sources for " +
                                std::to_string(in_elements.size()) + " inputs");
  return correspond(out_elements, in_elements, in_overlap, options, swatch.impl_.get(), sources, translation);
}

}  // namespace meshquilt
