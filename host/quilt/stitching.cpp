#include "quilt/stitching.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "quilt/element_deformation.h"

namespace meshquilt {
namespace {

uint64_t edge_key(int32_t a, int32_t b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

uint64_t undirected_key(int32_t a, int32_t b) { return a < b ? edge_key(a, b) : edge_key(b, a); }

double point_segment(const Vec3& p, const Vec3& a, const Vec3& b, double* lambda = nullptr) {
  const Vec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  if (lambda) *lambda = t;
  return glm::length(p - (a + t * ab));
}

//! Distance from p to the closed polyline through `pts`.
double point_polyline(const Vec3& p, const std::vector<Vec3>& pts) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < pts.size(); ++k) best = std::min(best, point_segment(p, pts[k], pts[(k + 1) % pts.size()]));
  return best;
}

//! Segment [s0, s1] against triangle (a, b, c), Moller-Trumbore with the segment's parameter
//! restricted to its length. Floating point: a cheap guard, not an exact predicate.
bool segment_hits_triangle(const Vec3& s0, const Vec3& s1, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 d = s1 - s0, e1 = b - a, e2 = c - a;
  const Vec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  const double scale = glm::length(d) * glm::length(e1) * glm::length(e2);
  if (std::abs(det) <= 1e-12 * scale) return false;
  const double inv = 1.0 / det;
  const Vec3 t = s0 - a;
  const double u = glm::dot(t, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = glm::cross(t, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double s = glm::dot(e2, q) * inv;
  return s >= 0.0 && s <= 1.0;
}

bool triangles_cross(const std::array<Vec3, 3>& t1, const std::array<Vec3, 3>& t2) {
  for (int k = 0; k < 3; ++k) {
    if (segment_hits_triangle(t1[k], t1[(k + 1) % 3], t2[0], t2[1], t2[2])) return true;
    if (segment_hits_triangle(t2[k], t2[(k + 1) % 3], t1[0], t1[1], t1[2])) return true;
  }
  return false;
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
      }
      t[k] = m;
    }
    fmap[f] = static_cast<int32_t>(part.triangles.size());
    part.triangles.push_back(t);
  }
  return part;
}

//! One seam point of an aligned loop pair: P vertex welded to a Q vertex, or one of them
//! splitting the other loop's edge (seg0 -> seg1 in seam order) at `lambda`.
struct SeamEvent {
  enum Kind : uint8_t { pair, p_alone, q_alone } kind = pair;
  int32_t p = -1, q = -1;        // loop positions (P index; Q index in the reversed, rotated loop)
  int32_t seg0 = -1, seg1 = -1;  // other loop's edge ends, loop positions
  double lambda = 0.0;
};

struct Alignment {
  double cost = std::numeric_limits<double>::infinity();
  int32_t q_start = 0;  // Q'_j = Qr[(q_start + j) % n]
  std::vector<SeamEvent> events;
};

//! Aligns closed polylines P (m points) and Q (n points, already running the same way as P) by
//! dynamic programming, P[0] welded to Q[0]. Every P and Q point takes part in exactly one event,
//! events in seam order; a point alone lands on the other loop's current edge.
Alignment align_loops(const std::vector<Vec3>& P, const std::vector<Vec3>& Q, double min_split) {
  const int32_t m = static_cast<int32_t>(P.size()), n = static_cast<int32_t>(Q.size());
  const double inf = std::numeric_limits<double>::infinity();
  const int32_t W = n + 1;
  std::vector<double> cost(static_cast<size_t>(m + 1) * W, inf);
  std::vector<uint8_t> from(static_cast<size_t>(m + 1) * W, 0);
  // A point landing near an end of the other edge would create a sliver, so the split stays
  // within [min_split, 1 - min_split] of the edge and pays for the distance to that point.
  auto alone_cost = [&](const Vec3& x, const Vec3& a, const Vec3& b, double* lambda) {
    point_segment(x, a, b, lambda);
    *lambda = std::clamp(*lambda, min_split, 1.0 - min_split);
    return glm::length(x - glm::mix(a, b, *lambda));
  };
  cost[1 * W + 1] = glm::length(P[0] - Q[0]);
  for (int32_t i = 1; i <= m; ++i) {
    for (int32_t j = 1; j <= n; ++j) {
      if (i == 1 && j == 1) continue;
      double best = inf;
      uint8_t how = 0;
      if (i >= 2 && j >= 2) {
        const double c = cost[(i - 1) * W + (j - 1)] + glm::length(P[i - 1] - Q[j - 1]);
        if (c < best) best = c, how = 1;
      }
      if (i >= 2) {
        double lam;
        const double c = cost[(i - 1) * W + j] + alone_cost(P[i - 1], Q[j - 1], Q[j % n], &lam);
        if (c < best) best = c, how = 2;
      }
      if (j >= 2) {
        double lam;
        const double c = cost[i * W + (j - 1)] + alone_cost(Q[j - 1], P[i - 1], P[i % m], &lam);
        if (c < best) best = c, how = 3;
      }
      cost[i * W + j] = best;
      from[i * W + j] = how;
    }
  }
  Alignment out;
  out.cost = cost[m * W + n];
  int32_t i = m, j = n;
  while (!(i == 1 && j == 1)) {
    SeamEvent e;
    switch (from[i * W + j]) {
      case 1: e.kind = SeamEvent::pair, e.p = i - 1, e.q = j - 1, --i, --j; break;
      case 2:
        e.kind = SeamEvent::p_alone, e.p = i - 1, e.seg0 = j - 1, e.seg1 = j % n;
        alone_cost(P[i - 1], Q[j - 1], Q[j % n], &e.lambda);
        --i;
        break;
      case 3:
        e.kind = SeamEvent::q_alone, e.q = j - 1, e.seg0 = i - 1, e.seg1 = i % m;
        alone_cost(Q[j - 1], P[i - 1], P[i % m], &e.lambda);
        --j;
        break;
      default: out.cost = inf; return out;
    }
    out.events.push_back(e);
  }
  out.events.push_back(SeamEvent{SeamEvent::pair, 0, 0, -1, -1, 0.0});
  std::reverse(out.events.begin(), out.events.end());
  // Points splitting the same edge form a run in seam order; their split parameters must rise
  // by at least min_split, or they are spread evenly along the edge.
  for (size_t r = 0; r < out.events.size();) {
    size_t s = r + 1;
    if (out.events[r].kind != SeamEvent::pair)
      while (s < out.events.size() && out.events[s].kind == out.events[r].kind && out.events[s].seg0 == out.events[r].seg0) ++s;
    bool spaced = true;
    for (size_t t = r + 1; t < s; ++t) spaced = spaced && out.events[t].lambda - out.events[t - 1].lambda >= min_split;
    if (!spaced)
      for (size_t t = r; t < s; ++t) out.events[t].lambda = static_cast<double>(t - r + 1) / static_cast<double>(s - r + 1);
    r = s;
  }
  return out;
}

//! Every edge shared by exactly two faces that traverse it in opposite directions.
bool closed_oriented(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& nb) {
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t g = nb[f][k];
      if (g < 0) return false;
      const int32_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      bool reverse = false;
      for (int j = 0; j < 3; ++j) reverse = reverse || (mesh.triangles[g][j] == b && mesh.triangles[g][(j + 1) % 3] == a);
      if (!reverse) return false;
    }
  return true;
}

StitchResult refuse(std::string why) {
  StitchResult r;
  r.failure = std::move(why);
  return r;
}

}  // namespace

std::vector<std::array<int32_t, 3>> face_neighbors(const TriMesh& mesh) {
  // Sorting (edge, face-slot) records groups each edge's faces without a hash map.
  struct Use {
    uint64_t key;
    int32_t face, slot;
  };
  std::vector<Use> uses;
  uses.reserve(mesh.num_faces() * 3);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      uses.push_back({undirected_key(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3]), static_cast<int32_t>(f), k});
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) { return x.key < y.key; });
  std::vector<std::array<int32_t, 3>> nb(mesh.num_faces(), {-1, -1, -1});
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 2) {
      nb[uses[i].face][uses[i].slot] = uses[i + 1].face;
      nb[uses[i + 1].face][uses[i + 1].slot] = uses[i].face;
    } else if (j - i > 2) {
      for (size_t k = i; k < j; ++k) nb[uses[k].face][uses[k].slot] = -2;
    }
    i = j;
  }
  return nb;
}

bool cut_loops(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& neighbors,
               const std::vector<uint8_t>& keep, std::vector<CutLoop>& loops, std::string* why) {
  loops.clear();
  // Outgoing boundary half-edges per vertex: (face, slot, is_cut).
  struct Out {
    int32_t face, slot;
    bool cut;
  };
  std::unordered_map<int32_t, std::vector<Out>> out;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!keep[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const int32_t g = neighbors[f][k];
      const bool cut = g >= 0 && !keep[g];
      if (g == -1 || cut) out[mesh.triangles[f][k]].push_back({static_cast<int32_t>(f), k, cut});
      if (g == -2) {
        if (why) *why = "kept face " + std::to_string(f) + " has a non-manifold edge";
        return false;
      }
    }
  }
  for (const auto& [v, list] : out)
    if (list.size() > 1) {
      if (why) *why = "the kept region is pinched at vertex " + std::to_string(v);
      return false;
    }
  std::unordered_map<int32_t, uint8_t> used;
  for (const auto& [start, list] : out) {
    if (used[start]) continue;
    CutLoop loop;
    bool any_cut = false, any_original = false;
    int32_t v = start;
    while (!used[v]) {
      used[v] = 1;
      const Out& o = out.at(v).front();
      loop.vertices.push_back(v);
      loop.faces.push_back(o.face);
      (o.cut ? any_cut : any_original) = true;
      v = mesh.triangles[o.face][(o.slot + 1) % 3];
      if (!out.count(v)) {
        if (why) *why = "a boundary chain ends at vertex " + std::to_string(v);
        return false;
      }
    }
    if (v != start) {
      if (why) *why = "boundary chains merge at vertex " + std::to_string(v);
      return false;
    }
    if (any_cut && any_original) {
      if (why) *why = "a cut loop runs along the element's own boundary";
      return false;
    }
    if (any_cut) loops.push_back(std::move(loop));
  }
  // Deterministic order: by smallest vertex index.
  std::sort(loops.begin(), loops.end(), [](const CutLoop& x, const CutLoop& y) {
    return *std::min_element(x.vertices.begin(), x.vertices.end()) <
           *std::min_element(y.vertices.begin(), y.vertices.end());
  });
  return true;
}

int32_t tidy_cut(const TriMesh& mesh, const std::vector<std::array<int32_t, 3>>& neighbors,
                 std::vector<uint8_t>& keep) {
  int32_t removed = 0;
  const size_t F = mesh.num_faces();
  for (int pass = 0; pass < 64; ++pass) {
    bool changed = false;
    for (size_t f = 0; f < F; ++f) {
      if (!keep[f]) continue;
      int cuts = 0;
      for (int k = 0; k < 3; ++k) cuts += neighbors[f][k] >= 0 && !keep[neighbors[f][k]];
      if (cuts >= 2) keep[f] = 0, ++removed, changed = true;
    }
    std::unordered_map<int32_t, int32_t> outgoing;
    for (size_t f = 0; f < F; ++f) {
      if (!keep[f]) continue;
      for (int k = 0; k < 3; ++k)
        if (neighbors[f][k] == -1 || (neighbors[f][k] >= 0 && !keep[neighbors[f][k]])) ++outgoing[mesh.triangles[f][k]];
    }
    for (size_t f = 0; f < F; ++f) {
      if (!keep[f]) continue;
      for (int k = 0; k < 3; ++k) {
        auto it = outgoing.find(mesh.triangles[f][k]);
        if (it != outgoing.end() && it->second > 1) {
          keep[f] = 0, ++removed, changed = true;
          break;
        }
      }
    }
    if (!changed) break;
  }
  return removed;
}

SurfaceReport inspect_surface(const TriMesh& mesh) {
  SurfaceReport r;
  std::vector<uint64_t> directed;
  directed.reserve(mesh.num_faces() * 3);
  for (const Tri& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) ++r.degenerate_faces;
    for (int k = 0; k < 3; ++k) directed.push_back(edge_key(t[k], t[(k + 1) % 3]));
  }
  std::sort(directed.begin(), directed.end());
  auto count_directed = [&](uint64_t key) {
    const auto range = std::equal_range(directed.begin(), directed.end(), key);
    return static_cast<int64_t>(range.second - range.first);
  };
  int64_t edges = 0;
  for (size_t i = 0; i < directed.size();) {
    size_t j = i;
    while (j < directed.size() && directed[j] == directed[i]) ++j;
    const auto a = static_cast<int32_t>(directed[i] >> 32), b = static_cast<int32_t>(directed[i] & 0xffffffffu);
    const int64_t forward = static_cast<int64_t>(j - i), backward = a == b ? 0 : count_directed(edge_key(b, a));
    // Each undirected edge is counted once, from its smaller-first direction or, when only the
    // larger-first direction exists, from that one.
    if (a < b || backward == 0) {
      ++edges;
      const int64_t uses = forward + backward;
      if (uses == 1) ++r.boundary_edges;
      else if (uses > 2) ++r.nonmanifold_edges;
      else if (forward != 1 || backward != 1) ++r.misoriented_edges;
    }
    i = j;
  }
  // Fans: faces around a vertex joined when they share an edge at that vertex.
  const size_t V = mesh.num_vertices();
  std::vector<int32_t> first(V + 1, 0), around(mesh.num_faces() * 3);
  for (const Tri& t : mesh.triangles)
    for (int32_t v : t) ++first[v + 1];
  for (size_t v = 0; v < V; ++v) first[v + 1] += first[v];
  std::vector<int32_t> fill(first.begin(), first.end() - 1);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f]) around[fill[v]++] = static_cast<int32_t>(f);
  std::vector<int32_t> parent(V);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  int64_t used = 0;
  std::vector<int32_t> fan;
  for (size_t v = 0; v < V; ++v) {
    const int32_t n = first[v + 1] - first[v];
    if (n == 0) continue;
    ++used;
    const int32_t* fs = &around[first[v]];
    fan.resize(n);
    std::iota(fan.begin(), fan.end(), 0);
    auto ffind = [&](int32_t x) {
      while (fan[x] != x) x = fan[x] = fan[fan[x]];
      return x;
    };
    for (int32_t i = 0; i < n; ++i)
      for (int32_t j = i + 1; j < n; ++j) {
        int shared = 0;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) shared += mesh.triangles[fs[i]][a] == mesh.triangles[fs[j]][b];
        if (shared >= 2) fan[ffind(i)] = ffind(j);
      }
    int fans = 0;
    for (int32_t i = 0; i < n; ++i) fans += ffind(i) == i;
    if (fans > 1) ++r.pinched_vertices;
  }
  for (const Tri& t : mesh.triangles) {
    parent[find(t[0])] = find(t[1]);
    parent[find(t[1])] = find(t[2]);
  }
  for (size_t v = 0; v < V; ++v)
    if (first[v + 1] > first[v] && find(static_cast<int32_t>(v)) == static_cast<int32_t>(v)) ++r.components;
  r.euler = used - edges + static_cast<int64_t>(mesh.num_faces());
  return r;
}

StitchResult stitch_parts(const TriMesh& a, const std::vector<uint8_t>& keep_a, const TriMesh& b,
                          const std::vector<uint8_t>& keep_b, const StitchOptions& options) {
  const auto nb_a = face_neighbors(a), nb_b = face_neighbors(b);
  std::vector<CutLoop> loops_a, loops_b;
  std::string why;
  if (!cut_loops(a, nb_a, keep_a, loops_a, &why)) return refuse("first part: " + why);
  if (!cut_loops(b, nb_b, keep_b, loops_b, &why)) return refuse("second part: " + why);
  if (loops_a.empty() || loops_a.size() != loops_b.size())
    return refuse("the parts have " + std::to_string(loops_a.size()) + " and " + std::to_string(loops_b.size()) +
                  " cut loops");
  for (const auto* set : {&loops_a, &loops_b})
    for (const CutLoop& l : *set)
      if (l.vertices.size() < 3) return refuse("a cut loop has fewer than three vertices");

  const bool closed_inputs = closed_oriented(a, nb_a) && closed_oriented(b, nb_b);

  std::vector<int32_t> vmap_a, vmap_b, fmap_a, fmap_b;
  TriMesh pa = extract(a, keep_a, vmap_a, fmap_a);
  TriMesh pb = extract(b, keep_b, vmap_b, fmap_b);
  for (auto* set : {&loops_a, &loops_b}) {
    const bool is_a = set == &loops_a;
    for (CutLoop& l : *set) {
      for (int32_t& v : l.vertices) v = (is_a ? vmap_a : vmap_b)[v];
      for (int32_t& f : l.faces) f = (is_a ? fmap_a : fmap_b)[f];
    }
  }
  auto loop_points = [](const TriMesh& m, const CutLoop& l) {
    std::vector<Vec3> pts;
    for (int32_t v : l.vertices) pts.push_back(m.positions[v]);
    return pts;
  };

  // Pair loops one-to-one: each loop's nearest partner (mean distance of its points to the other
  // polyline) must choose it back.
  const size_t L = loops_a.size();
  std::vector<std::vector<Vec3>> pts_a(L), pts_b(L);
  for (size_t i = 0; i < L; ++i) pts_a[i] = loop_points(pa, loops_a[i]), pts_b[i] = loop_points(pb, loops_b[i]);
  auto mean_distance = [](const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    double s = 0.0;
    for (const Vec3& p : from) s += point_polyline(p, to);
    return s / static_cast<double>(from.size());
  };
  std::vector<int32_t> partner_of_a(L), partner_of_b(L);
  for (size_t i = 0; i < L; ++i) {
    double best_ab = std::numeric_limits<double>::infinity(), best_ba = best_ab;
    for (size_t j = 0; j < L; ++j) {
      const double ab = mean_distance(pts_a[i], pts_b[j]);
      if (ab < best_ab) best_ab = ab, partner_of_a[i] = static_cast<int32_t>(j);
      const double ba = mean_distance(pts_b[i], pts_a[j]);
      if (ba < best_ba) best_ba = ba, partner_of_b[i] = static_cast<int32_t>(j);
    }
  }
  for (size_t i = 0; i < L; ++i)
    if (partner_of_b[partner_of_a[i]] != static_cast<int32_t>(i)) return refuse("the cut loops do not pair up one-to-one");

  const double edge = std::max(mean_edge_length(pa), mean_edge_length(pb));

  // Align each pair. Q runs reversed so that both loops go the same way along the seam: the parts
  // lie on opposite sides of it, each to the left of its own loop.
  struct PairPlan {
    int32_t ia, ib;
    std::vector<int32_t> qv;  // part-b vertex of Q'_j
    Alignment alignment;
  };
  std::vector<PairPlan> plans;
  for (size_t i = 0; i < L; ++i) {
    PairPlan plan{static_cast<int32_t>(i), partner_of_a[i], {}, {}};
    const std::vector<Vec3>& P = pts_a[i];
    std::vector<int32_t> qr(loops_b[plan.ib].vertices.rbegin(), loops_b[plan.ib].vertices.rend());
    const int32_t n = static_cast<int32_t>(qr.size()), m = static_cast<int32_t>(P.size());
    // Direction check: tangents of P and reversed Q must agree on average.
    double agree = 0.0;
    for (int32_t k = 0; k < m; ++k) {
      int32_t c = 0;
      double dc = std::numeric_limits<double>::infinity();
      for (int32_t j = 0; j < n; ++j) {
        const double d = glm::length(P[k] - pb.positions[qr[j]]);
        if (d < dc) dc = d, c = j;
      }
      const Vec3 tp = P[(k + 1) % m] - P[(k + m - 1) % m];
      const Vec3 tq = pb.positions[qr[(c + 1) % n]] - pb.positions[qr[(c + n - 1) % n]];
      const double lp = glm::length(tp), lq = glm::length(tq);
      if (lp > 0 && lq > 0) agree += glm::dot(tp, tq) / (lp * lq);
    }
    if (agree <= 0.0) return refuse("a loop pair runs the same way: the parts are not consistently oriented");
    std::vector<int32_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int32_t x, int32_t y) {
      return glm::length(P[0] - pb.positions[qr[x]]) < glm::length(P[0] - pb.positions[qr[y]]);
    });
    const int32_t tries = std::min<int32_t>(n, std::max<int32_t>(1, options.start_candidates));
    for (int32_t t = 0; t < tries; ++t) {
      std::vector<Vec3> Q(n);
      std::vector<int32_t> qv(n);
      for (int32_t j = 0; j < n; ++j) qv[j] = qr[(order[t] + j) % n], Q[j] = pb.positions[qv[j]];
      Alignment al = align_loops(P, Q, options.min_split);
      if (al.cost < plan.alignment.cost) plan.alignment = std::move(al), plan.qv = std::move(qv);
    }
    if (!std::isfinite(plan.alignment.cost)) return refuse("no alignment of a loop pair");
    plans.push_back(std::move(plan));
  }

  // Seam points in terms of each part's positions; `seam_point` averages the two sides.
  auto side_points = [&](const PairPlan& plan, const SeamEvent& e, const std::vector<Vec3>& xa,
                         const std::vector<Vec3>& xb, Vec3& on_a, Vec3& on_b) {
    const CutLoop& la = loops_a[plan.ia];
    const int32_t m = static_cast<int32_t>(la.vertices.size());
    switch (e.kind) {
      case SeamEvent::pair: on_a = xa[la.vertices[e.p]], on_b = xb[plan.qv[e.q]]; break;
      case SeamEvent::p_alone:
        on_a = xa[la.vertices[e.p]];
        on_b = glm::mix(xb[plan.qv[e.seg0]], xb[plan.qv[e.seg1]], e.lambda);
        break;
      case SeamEvent::q_alone:
        on_b = xb[plan.qv[e.q]];
        on_a = glm::mix(xa[la.vertices[e.seg0 % m]], xa[la.vertices[e.seg1 % m]], e.lambda);
        break;
    }
  };

  // Eq. 5 with the loop vertices pulled to the averaged seam points; far vertices anchored.
  std::vector<VertexConstraint> ca, cb;
  std::vector<Vec3> seam_a_pts;
  for (const PairPlan& plan : plans)
    for (const SeamEvent& e : plan.alignment.events) {
      Vec3 on_a, on_b;
      side_points(plan, e, pa.positions, pb.positions, on_a, on_b);
      const Vec3 target = 0.5 * (on_a + on_b);
      if (e.kind != SeamEvent::q_alone) ca.push_back({loops_a[plan.ia].vertices[e.p], target});
      if (e.kind != SeamEvent::p_alone) cb.push_back({plan.qv[e.q], target});
      seam_a_pts.push_back(target);
    }
  DeformationOptions deform;
  deform.mu = options.mu;
  // Vertices beyond the anchor reach stay where they are, so only the band of faces touching a
  // vertex within reach is solved (its outer vertices anchored): the system stays a few rings
  // wide however large the element.
  auto deform_near_seam = [&](const TriMesh& part, const std::vector<VertexConstraint>& seam_cons) {
    if (options.anchor_factor <= 0.0) return deform_with_vertex_constraints(part, seam_cons, deform);
    const double reach = options.anchor_factor * edge;
    std::vector<uint8_t> free(part.num_vertices(), 0);
    for (size_t v = 0; v < part.num_vertices(); ++v)
      for (const Vec3& s : seam_a_pts)
        if (glm::length(part.positions[v] - s) <= reach) {
          free[v] = 1;
          break;
        }
    TriMesh band;
    std::vector<int32_t> local(part.num_vertices(), -1), global;
    for (const Tri& t : part.triangles) {
      if (!free[t[0]] && !free[t[1]] && !free[t[2]]) continue;
      Tri u;
      for (int k = 0; k < 3; ++k) {
        if (local[t[k]] < 0) {
          local[t[k]] = static_cast<int32_t>(global.size());
          global.push_back(t[k]);
          band.positions.push_back(part.positions[t[k]]);
        }
        u[k] = local[t[k]];
      }
      band.triangles.push_back(u);
    }
    std::vector<VertexConstraint> cons;
    for (const VertexConstraint& c : seam_cons)
      if (local[c.vertex] >= 0) cons.push_back({local[c.vertex], c.target});
    for (size_t l = 0; l < global.size(); ++l)
      if (!free[global[l]]) cons.push_back({static_cast<int32_t>(l), part.positions[global[l]]});
    const std::vector<Vec3> moved = deform_with_vertex_constraints(band, cons, deform);
    std::vector<Vec3> x = part.positions;
    for (size_t l = 0; l < global.size(); ++l)
      if (free[global[l]]) x[global[l]] = moved[l];
    return x;
  };
  const std::vector<Vec3> xa = deform_near_seam(pa, ca);
  const std::vector<Vec3> xb = deform_near_seam(pb, cb);

  // Assemble: part a's vertices, then part b's; a welded Q vertex becomes its P partner.
  const int32_t Va = static_cast<int32_t>(pa.num_vertices());
  TriMesh out;
  out.positions = xa;
  out.positions.insert(out.positions.end(), xb.begin(), xb.end());
  std::vector<int32_t> bmap(pb.num_vertices());
  for (size_t v = 0; v < bmap.size(); ++v) bmap[v] = Va + static_cast<int32_t>(v);
  // Splits: boundary face -> ordered vertex ids inserted on its boundary half-edge.
  std::unordered_map<int32_t, std::vector<int32_t>> split_a, split_b;
  std::vector<int32_t> seam_vertices;
  for (const PairPlan& plan : plans) {
    const CutLoop& la = loops_a[plan.ia];
    const int32_t m = static_cast<int32_t>(la.vertices.size());
    // Part b's boundary half-edge on Q' segment (j-1, j) is Q'_j -> Q'_{j-1}; find its face.
    std::unordered_map<uint64_t, int32_t> b_face;
    const CutLoop& lb = loops_b[plan.ib];
    for (size_t k = 0; k < lb.vertices.size(); ++k)
      b_face[edge_key(lb.vertices[k], lb.vertices[(k + 1) % lb.vertices.size()])] = lb.faces[k];
    for (const SeamEvent& e : plan.alignment.events) {
      Vec3 on_a, on_b;
      side_points(plan, e, xa, xb, on_a, on_b);
      const Vec3 s = 0.5 * (on_a + on_b);
      switch (e.kind) {
        case SeamEvent::pair:
          out.positions[la.vertices[e.p]] = s;
          bmap[plan.qv[e.q]] = la.vertices[e.p];
          seam_vertices.push_back(la.vertices[e.p]);
          break;
        case SeamEvent::p_alone: {
          out.positions[la.vertices[e.p]] = s;
          const auto it = b_face.find(edge_key(plan.qv[e.seg1], plan.qv[e.seg0]));
          if (it == b_face.end()) return refuse("internal: seam edge not on part b's loop");
          split_b[it->second].push_back(la.vertices[e.p]);
          seam_vertices.push_back(la.vertices[e.p]);
          break;
        }
        case SeamEvent::q_alone: {
          out.positions[Va + plan.qv[e.q]] = s;
          split_a[la.faces[e.seg0 % m]].push_back(Va + plan.qv[e.q]);
          seam_vertices.push_back(Va + plan.qv[e.q]);
          break;
        }
      }
    }
  }
  // Split a boundary face (v0 -> v1 its boundary half-edge, c opposite) into a fan, keeping its
  // winding; `ins` runs from v0 to v1.
  std::vector<std::pair<Tri, Vec3>> new_faces;  // with the normal of the face they replace
  auto emit = [&](const TriMesh& part, const std::vector<Vec3>& x, size_t f, const std::vector<int32_t>& idmap,
                  const std::vector<std::array<int32_t, 3>>& nbp, const std::vector<uint8_t>* is_loop_edge_slot,
                  const std::vector<int32_t>* ins, bool reverse_ins, int32_t slot) {
    Tri t{idmap[part.triangles[f][0]], idmap[part.triangles[f][1]], idmap[part.triangles[f][2]]};
    if (!ins || ins->empty()) {
      out.triangles.push_back(t);
      return;
    }
    const Vec3 n0 = glm::cross(x[part.triangles[f][1]] - x[part.triangles[f][0]], x[part.triangles[f][2]] - x[part.triangles[f][0]]);
    std::vector<int32_t> chain{t[slot]};
    if (reverse_ins) chain.insert(chain.end(), ins->rbegin(), ins->rend());
    else chain.insert(chain.end(), ins->begin(), ins->end());
    chain.push_back(t[(slot + 1) % 3]);
    const int32_t c = t[(slot + 2) % 3];
    for (size_t k = 0; k + 1 < chain.size(); ++k) {
      out.triangles.push_back({chain[k], chain[k + 1], c});
      new_faces.push_back({out.triangles.back(), n0});
    }
  };
  // Which slot of a boundary face carries its loop edge.
  auto loop_slot = [](const TriMesh& part, const std::vector<CutLoop>& loops, std::unordered_map<int32_t, int32_t>& slot) {
    for (const CutLoop& l : loops)
      for (size_t k = 0; k < l.vertices.size(); ++k) {
        const Tri& t = part.triangles[l.faces[k]];
        for (int s = 0; s < 3; ++s)
          if (t[s] == l.vertices[k]) slot[l.faces[k]] = s;
      }
  };
  std::unordered_map<int32_t, int32_t> slot_a, slot_b;
  loop_slot(pa, loops_a, slot_a);
  loop_slot(pb, loops_b, slot_b);
  std::vector<int32_t> amap(pa.num_vertices());
  std::iota(amap.begin(), amap.end(), 0);
  // A face carrying two loop edges would need a two-sided split; tidy_cut removes such ears.
  for (const auto& [f, ins] : split_a) {
    int count = 0;
    for (const CutLoop& l : loops_a) count += static_cast<int>(std::count(l.faces.begin(), l.faces.end(), f));
    if (count > 1) return refuse("a seam face has two cut edges");
  }
  for (const auto& [f, ins] : split_b) {
    int count = 0;
    for (const CutLoop& l : loops_b) count += static_cast<int>(std::count(l.faces.begin(), l.faces.end(), f));
    if (count > 1) return refuse("a seam face has two cut edges");
  }
  for (size_t f = 0; f < pa.num_faces(); ++f) {
    auto it = split_a.find(static_cast<int32_t>(f));
    emit(pa, xa, f, amap, nb_a, nullptr, it == split_a.end() ? nullptr : &it->second, false,
         it == split_a.end() ? 0 : slot_a.at(static_cast<int32_t>(f)));
  }
  const size_t faces_from_a = out.triangles.size();
  for (size_t f = 0; f < pb.num_faces(); ++f) {
    auto it = split_b.find(static_cast<int32_t>(f));
    emit(pb, xb, f, bmap, nb_b, nullptr, it == split_b.end() ? nullptr : &it->second, true,
         it == split_b.end() ? 0 : slot_b.at(static_cast<int32_t>(f)));
  }

  // Compact: drop part-b vertices welded away.
  std::vector<int32_t> remap(out.positions.size(), -1);
  TriMesh result;
  for (Tri& t : out.triangles)
    for (int32_t& v : t) {
      if (remap[v] < 0) remap[v] = static_cast<int32_t>(result.positions.size()), result.positions.push_back(out.positions[v]);
      v = remap[v];
    }
  result.triangles = std::move(out.triangles);

  // Checks.
  for (const Tri& t : result.triangles) {
    const Vec3 &p = result.positions[t[0]], &q = result.positions[t[1]], &r = result.positions[t[2]];
    const double area2 = glm::length(glm::cross(q - p, r - p));
    const double longest = std::max({glm::length(q - p), glm::length(r - q), glm::length(p - r)});
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(area2 > 1e-6 * longest * longest))
      return refuse("the seam created a degenerate triangle");
  }
  for (auto& [t, n0] : new_faces) {
    Tri u = t;
    for (int32_t& v : u) v = remap[v];
    const Vec3 n = glm::cross(result.positions[u[1]] - result.positions[u[0]], result.positions[u[2]] - result.positions[u[0]]);
    if (glm::dot(n, n0) <= 0.0) return refuse("a split seam face flipped");
  }
  const SurfaceReport report = inspect_surface(result);
  if (report.components != 1) return refuse("the stitched element has " + std::to_string(report.components) + " components");
  if (report.nonmanifold_edges || report.misoriented_edges || report.pinched_vertices || report.degenerate_faces)
    return refuse("the stitched element is not an oriented manifold");
  if (closed_inputs && !report.closed_manifold()) return refuse("the stitched element is not closed");
  if (options.check_intersections) {
    std::vector<uint8_t> on_seam(result.num_vertices(), 0);
    for (int32_t v : seam_vertices) on_seam[remap[v]] = 1;
    std::vector<std::array<Vec3, 3>> tri(result.num_faces());
    std::vector<std::array<Vec3, 2>> box(result.num_faces());
    for (size_t f = 0; f < result.num_faces(); ++f) {
      for (int k = 0; k < 3; ++k) tri[f][k] = result.positions[result.triangles[f][k]];
      box[f][0] = glm::min(glm::min(tri[f][0], tri[f][1]), tri[f][2]);
      box[f][1] = glm::max(glm::max(tri[f][0], tri[f][1]), tri[f][2]);
    }
    // Candidates through a hash grid of face boxes (cells of about two edge lengths), so only
    // faces near the seam are tested.
    const double cell = std::max(2.0 * edge, 1e-12);
    auto cell_of = [&](double x) { return static_cast<int64_t>(std::floor(x / cell)); };
    auto cell_key = [](int64_t i, int64_t j, int64_t k) {
      return static_cast<uint64_t>((i * 73856093) ^ (j * 19349663) ^ (k * 83492791));
    };
    std::unordered_map<uint64_t, std::vector<int32_t>> grid;
    for (size_t f = 0; f < result.num_faces(); ++f)
      for (int64_t i = cell_of(box[f][0].x); i <= cell_of(box[f][1].x); ++i)
        for (int64_t j = cell_of(box[f][0].y); j <= cell_of(box[f][1].y); ++j)
          for (int64_t k = cell_of(box[f][0].z); k <= cell_of(box[f][1].z); ++k)
            grid[cell_key(i, j, k)].push_back(static_cast<int32_t>(f));
    std::vector<int32_t> stamp(result.num_faces(), -1);
    for (size_t f = 0; f < result.num_faces(); ++f) {
      const Tri& t = result.triangles[f];
      const bool seam_face = on_seam[t[0]] || on_seam[t[1]] || on_seam[t[2]];
      const bool from_a = f < faces_from_a;
      // Part b's faces only meet part a's here (seam faces meet everything); each part's own
      // faces were as they were before stitching.
      if (!seam_face && !from_a) continue;
      for (int64_t i = cell_of(box[f][0].x); i <= cell_of(box[f][1].x); ++i)
        for (int64_t j = cell_of(box[f][0].y); j <= cell_of(box[f][1].y); ++j)
          for (int64_t k = cell_of(box[f][0].z); k <= cell_of(box[f][1].z); ++k) {
            const auto it = grid.find(cell_key(i, j, k));
            if (it == grid.end()) continue;
            for (int32_t g : it->second) {
              if (g == static_cast<int32_t>(f) || stamp[g] == static_cast<int32_t>(f)) continue;
              stamp[g] = static_cast<int32_t>(f);
              if (!seam_face && static_cast<size_t>(g) < faces_from_a) continue;
              const auto& bg = box[g];
              const auto& bf = box[f];
              if (bg[1].x < bf[0].x || bg[1].y < bf[0].y || bg[1].z < bf[0].z || bg[0].x > bf[1].x ||
                  bg[0].y > bf[1].y || bg[0].z > bf[1].z)
                continue;
              const Tri& u = result.triangles[g];
              bool shares = false;
              for (int a = 0; a < 3; ++a)
                for (int b2 = 0; b2 < 3; ++b2) shares = shares || t[a] == u[b2];
              if (!shares && triangles_cross(tri[f], tri[g]))
                return refuse(seam_face ? "a seam face intersects another face" : "the two parts intersect away from the seam");
            }
          }
    }
  }
  StitchResult ok;
  ok.ok = true;
  ok.mesh = std::move(result);
  ok.loop_pairs = static_cast<int32_t>(L);
  return ok;
}

}  // namespace meshquilt
