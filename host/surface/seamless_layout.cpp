#include "surface/seamless_layout.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include <Eigen/Sparse>
#include <glm/geometric.hpp>

#include "core/constants.h"
#include "mesh/disjoint_sets.h"
#include "numerics/sparse_solve.h"
#include "quilt/swatch_lattice.h"

namespace meshquilt {
namespace {

int corner_of(const Tri& t, int32_t v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; }

// The rotation index of a turn by `angle` against the field's period, in [0, n).
int turn_index(double angle, int n) {
  const double period = 2.0 * kPi / n;
  const long k = std::lround(angle / period);
  return static_cast<int>(((k % n) + n) % n);
}

// Rotates each face's direction by a multiple of 2 pi / n so that neighbours across a spanning
// tree of faces agree (the field's "combing"); marks the tree's edges.
void comb(const BaseSurface& base, const DirectionField& field, SeamlessLayout& layout,
          std::vector<std::array<uint8_t, 3>>& tree) {
  const TriMesh& mesh = base.mesh;
  const size_t faces = mesh.num_faces();
  const double period = 2.0 * kPi / field.symmetry;
  layout.axis = field.directions;
  tree.assign(faces, {0, 0, 0});
  std::vector<uint8_t> reached(faces, 0);
  std::deque<int32_t> queue;
  for (size_t root = 0; root < faces; ++root) {
    if (reached[root]) continue;
    reached[root] = 1;
    queue.push_back(static_cast<int32_t>(root));
    while (!queue.empty()) {
      const int32_t f = queue.front();
      queue.pop_front();
      const Tri& t = mesh.triangles[f];
      for (int k = 0; k < 3; ++k) {
        const int32_t g = base.face_across[f][k];
        if (g < 0 || reached[g]) continue;
        reached[g] = 1;
        const Vec3 carried = transport_across(base, f, g, t[k], t[(k + 1) % 3], layout.axis[f]);
        const Vec3 n = base.face_normals[g];
        const double angle = signed_angle(carried, layout.axis[g], n);
        // Turn g's direction back by the whole periods between it and f's.
        const double back = -period * std::round(angle / period);
        layout.axis[g] = std::cos(back) * layout.axis[g] + std::sin(back) * glm::cross(n, layout.axis[g]);
        tree[f][k] = 1;
        tree[g][corner_of(mesh.triangles[g], t[(k + 1) % 3])] = 1;
        queue.push_back(g);
      }
    }
  }
}

// Seams: interior edges off the tree, less branches that dangle from a vertex that needs no cut
// (not a cone, not on a boundary), pruned while the edge carries no turn.
void cut_open(const BaseSurface& base, const std::vector<std::array<uint8_t, 3>>& tree, SeamlessLayout& layout) {
  const TriMesh& mesh = base.mesh;
  const size_t faces = mesh.num_faces();
  std::vector<uint8_t> keeps_cuts(mesh.num_vertices(), 0);
  for (int32_t v : layout.cones) keeps_cuts[v] = 1;
  layout.cut.assign(faces, {0, 0, 0});
  std::vector<int> degree(mesh.num_vertices(), 0);
  for (size_t f = 0; f < faces; ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (g < 0) {
        keeps_cuts[t[k]] = keeps_cuts[t[(k + 1) % 3]] = 1;
        continue;
      }
      if (tree[f][k]) continue;
      layout.cut[f][k] = 1;
      if (static_cast<size_t>(g) > f) ++degree[t[k]], ++degree[t[(k + 1) % 3]];
    }
  }
  // The cut edge at a vertex, as (face, edge) from the lower face.
  const auto cut_edge_at = [&](int32_t v, int32_t& f_out, int& k_out) {
    for (int32_t f : base.vertex_faces[v]) {
      const Tri& t = mesh.triangles[f];
      for (int k = 0; k < 3; ++k)
        if (layout.cut[f][k] && (t[k] == v || t[(k + 1) % 3] == v)) {
          f_out = f;
          k_out = k;
          return true;
        }
    }
    return false;
  };
  std::vector<int32_t> stack;
  for (size_t v = 0; v < mesh.num_vertices(); ++v)
    if (degree[v] == 1 && !keeps_cuts[v]) stack.push_back(static_cast<int32_t>(v));
  while (!stack.empty()) {
    const int32_t v = stack.back();
    stack.pop_back();
    int32_t f = -1;
    int k = 0;
    if (degree[v] != 1 || !cut_edge_at(v, f, k) || layout.turn[f][k] != 0) continue;
    const Tri& t = mesh.triangles[f];
    const int32_t g = base.face_across[f][k];
    const int32_t w = t[k] == v ? t[(k + 1) % 3] : t[k];
    layout.cut[f][k] = 0;
    layout.cut[g][corner_of(mesh.triangles[g], t[(k + 1) % 3])] = 0;
    --degree[v];
    if (--degree[w] == 1 && !keeps_cuts[w]) stack.push_back(w);
  }
}

// Layout vertices: face corners joined across the edges that are not cut.
int32_t make_wedges(const BaseSurface& base, SeamlessLayout& layout) {
  const TriMesh& mesh = base.mesh;
  const size_t corners = 3 * mesh.num_faces();
  DisjointSets wedges(corners);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (g < 0 || layout.cut[f][k]) continue;
      for (int32_t v : {t[k], t[(k + 1) % 3]})
        wedges.unite(static_cast<int32_t>(3 * f) + corner_of(t, v), 3 * g + corner_of(mesh.triangles[g], v));
    }
  }
  // Numbered in order of their first corner, whichever corner the sets take as root.
  layout.corner_wedge.assign(corners, -1);
  std::unordered_map<int32_t, int32_t> wedge_of_root;
  for (size_t c = 0; c < corners; ++c) {
    const auto [it, fresh] = wedge_of_root.emplace(wedges.find(static_cast<int32_t>(c)), static_cast<int32_t>(wedge_of_root.size()));
    layout.corner_wedge[c] = it->second;
  }
  return static_cast<int32_t>(wedge_of_root.size());
}

// The layout with the seams' transitions held by a stiff penalty. Per face, with X the axis and
// Y = normal x X: grad u along X, grad v along Y, both of one length (conformal), so the layout
// may take whatever even scale makes the field a gradient; and, weakly, that length 1.
// A cut edge from its lower face f (edge k, ends a and b) to g, with the layout vertices on
// either side of each end.
struct SeamEdge {
  int32_t f = -1;
  int k = 0;
  int32_t a = -1, b = -1;
  int32_t fa = -1, fb = -1, ga = -1, gb = -1;
};

std::vector<SeamEdge> seam_edges(const BaseSurface& base, const SeamlessLayout& layout) {
  const TriMesh& mesh = base.mesh;
  std::vector<SeamEdge> edges;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (!layout.cut[f][k] || static_cast<size_t>(g) < f) continue;
      const Tri& tg = mesh.triangles[g];
      SeamEdge e;
      e.f = static_cast<int32_t>(f);
      e.k = k;
      e.a = t[k];
      e.b = t[(k + 1) % 3];
      e.fa = layout.corner_wedge[3 * f + k];
      e.fb = layout.corner_wedge[3 * f + (k + 1) % 3];
      e.ga = layout.corner_wedge[3 * g + corner_of(tg, e.a)];
      e.gb = layout.corner_wedge[3 * g + corner_of(tg, e.b)];
      edges.push_back(e);
    }
  }
  return edges;
}

// Seams whose translation is held (#F x 3, on the edges from the lower face).
struct SeamHold {
  std::vector<std::array<glm::dvec2, 3>> translation;
  std::vector<std::array<uint8_t, 3>> held;
};

// unit: the length grad u and grad v are weakly held at.
void solve_layout(const BaseSurface& base, SeamlessLayout& layout, int32_t wedges, double unit, double size_hold,
                  const SeamHold* hold) {
  const TriMesh& mesh = base.mesh;
  const int quarter = 4 / layout.symmetry;  // quarter turns per unit of turn
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(2 * wedges, 1);
  double diagonal = 0.0;
  // Adds weight x (sum of coefficient x unknown - value)^2.
  const auto add_row = [&](const std::vector<std::pair<int32_t, double>>& row, double value, double weight) {
    for (const auto& [i, wi] : row) {
      rhs(i, 0) += weight * wi * value;
      for (const auto& [j, wj] : row) triplets.emplace_back(i, j, weight * wi * wj);
    }
  };
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    const double area = base.face_areas[f];
    if (area <= 0.0) continue;
    const Vec3 normal = base.face_normals[f];
    const Vec3 x = layout.axis[f], y = glm::cross(normal, x);
    std::vector<std::pair<int32_t, double>> ux, uy, vx, vy;  // grad u . X, ...
    for (int k = 0; k < 3; ++k) {
      const Vec3 g = glm::cross(normal, mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[(k + 1) % 3]]) / (2.0 * area);
      const int32_t w = layout.corner_wedge[3 * f + k];
      ux.emplace_back(2 * w, glm::dot(g, x));
      uy.emplace_back(2 * w, glm::dot(g, y));
      vx.emplace_back(2 * w + 1, glm::dot(g, x));
      vy.emplace_back(2 * w + 1, glm::dot(g, y));
      diagonal = std::max(diagonal, area * glm::dot(g, g));
    }
    std::vector<std::pair<int32_t, double>> conformal = ux;
    for (const auto& [i, c] : vy) conformal.emplace_back(i, -c);
    add_row(uy, 0.0, area);
    add_row(vx, 0.0, area);
    add_row(conformal, 0.0, area);
    add_row(ux, unit, size_hold * area);
    add_row(vy, unit, size_hold * area);
  }
  // Seams: (U_g(a) - U_g(b)) - R(-turn) (U_f(a) - U_f(b)) = 0, both coordinates.
  const double stiff = 1e10 * std::max(diagonal, 1e-300);
  for (const SeamEdge& e : seam_edges(base, layout)) {
    // R(-turn) as a 2 x 2 matrix from its action on the axes.
    const glm::dvec2 ex = quarter_turned({1.0, 0.0}, quarter * layout.turn[e.f][e.k]);
    const glm::dvec2 ey = quarter_turned({0.0, 1.0}, quarter * layout.turn[e.f][e.k]);
    for (int row = 0; row < 2; ++row) {
      if (hold && hold->held[e.f][e.k]) {
        // U_g(x) - R U_f(x) = translation, at both ends.
        for (const auto& [gx, fx] : {std::pair{e.ga, e.fa}, std::pair{e.gb, e.fb}})
          add_row({{2 * gx + row, 1.0}, {2 * fx, -ex[row]}, {2 * fx + 1, -ey[row]}}, hold->translation[e.f][e.k][row], stiff);
        continue;
      }
      const std::pair<int32_t, double> terms[6] = {{2 * e.ga + row, 1.0}, {2 * e.gb + row, -1.0},
                                                   {2 * e.fa, -ex[row]},   {2 * e.fa + 1, -ey[row]},
                                                   {2 * e.fb, ex[row]},    {2 * e.fb + 1, ey[row]}};
      for (const auto& [i, wi] : terms)
        for (const auto& [j, wj] : terms)
          if (wi != 0.0 && wj != 0.0) triplets.emplace_back(i, j, stiff * wi * wj);
    }
  }
  // Each piece's translation is free: a faint pull to the origin makes it definite.
  for (int32_t k = 0; k < 2 * wedges; ++k) triplets.emplace_back(k, k, 1e-10 * std::max(diagonal, 1e-300));
  Eigen::SparseMatrix<double> A(2 * wedges, 2 * wedges);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd x = solve_positive_definite(A, rhs, "seamless layout");
  layout.uv.resize(static_cast<size_t>(wedges));
  for (int32_t w = 0; w < wedges; ++w) layout.uv[w] = {x(2 * w, 0), x(2 * w + 1, 0)};
}

// Scales the layout so that its median scale (the square root of layout area over base area)
// is 1: the texture's size is what was asked for over most of the base, each face weighted by
// its base area. by_elements: weighted by the geometric mean of base and layout areas instead.
// Elements on a lattice are as many as the layout area holds, so the median by base area
// leaves the median ring small where the scale spreads (bunny 0.87 of the asked size), and the
// median by layout area overshoots (1.06-1.08); between the two it is within 5%. Yarns keep the
// base area: by the mean they are shorter in swatch lengths (1.85 against 1.99 over the bunny)
// and some ends meet (decision 0037).
// Returns the factor the layout was divided by.
double normalize_scale(const BaseSurface& base, SeamlessLayout& layout, bool by_elements) {
  std::vector<std::pair<double, double>> scales;  // (scale, weight)
  double total = 0.0;
  for (size_t f = 0; f < base.mesh.num_faces(); ++f) {
    if (base.face_areas[f] <= 0.0) continue;
    const glm::dvec2 a = layout.uv[layout.corner_wedge[3 * f]], b = layout.uv[layout.corner_wedge[3 * f + 1]],
                     c = layout.uv[layout.corner_wedge[3 * f + 2]];
    const double area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    if (area <= 0.0) continue;
    const double scale = std::sqrt(area / base.face_areas[f]);
    const double weight = by_elements ? base.face_areas[f] * scale : base.face_areas[f];
    scales.emplace_back(scale, weight);
    total += weight;
  }
  if (scales.empty()) return 1.0;
  std::sort(scales.begin(), scales.end());
  double below = 0.0;
  for (const auto& [scale, area] : scales) {
    below += area;
    if (below < 0.5 * total) continue;
    for (glm::dvec2& p : layout.uv) p /= scale;
    return scale;
  }
  return 1.0;
}

// One seam: cut edges joined end to end through the same pair of layout vertices, which share
// one translation. side: +1 for an edge oriented as the first, -1 for one reversed.
struct Seam {
  std::vector<size_t> edges;
  std::vector<int8_t> sides;
};

std::vector<Seam> join_seams(const BaseSurface& base, const SeamlessLayout& layout, const std::vector<SeamEdge>& edges) {
  std::map<std::array<int32_t, 3>, std::vector<std::pair<size_t, int32_t>>> at_end;  // -> (edge, its f side)
  const auto key = [](int32_t v, int32_t p, int32_t q) { return std::array<int32_t, 3>{v, std::min(p, q), std::max(p, q)}; };
  // At a cone the two sides of a seam are related by different turns through either edge.
  std::vector<uint8_t> cone(base.mesh.num_vertices(), 0);
  for (int32_t v : layout.cones) cone[v] = 1;
  for (size_t i = 0; i < edges.size(); ++i) {
    const SeamEdge& e = edges[i];
    if (e.fa != e.ga && !cone[e.a]) at_end[key(e.a, e.fa, e.ga)].emplace_back(i, e.fa);
    if (e.fb != e.gb && !cone[e.b]) at_end[key(e.b, e.fb, e.gb)].emplace_back(i, e.fb);
  }
  std::vector<int8_t> side(edges.size(), 0);
  std::vector<Seam> seams;
  for (size_t root = 0; root < edges.size(); ++root) {
    if (side[root] != 0) continue;
    side[root] = 1;
    Seam seam;
    std::vector<size_t> stack{root};
    seam.edges.push_back(root);
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      const SeamEdge& e = edges[i];
      for (const auto& [v, fv, gv] : {std::tuple{e.a, e.fa, e.ga}, std::tuple{e.b, e.fb, e.gb}}) {
        if (fv == gv || cone[v]) continue;
        for (const auto& [j, fj] : at_end[key(v, fv, gv)]) {
          if (side[j] != 0) continue;
          side[j] = static_cast<int8_t>(fj == fv ? side[i] : -side[i]);
          seam.edges.push_back(j);
          stack.push_back(j);
        }
      }
    }
    for (size_t i : seam.edges) seam.sides.push_back(side[i]);
    seams.push_back(std::move(seam));
  }
  return seams;
}

// Rounds the seams' translations to periods of the lattice greedily (Bommes et al. 2009): the
// seams nearest a period first, a third of those left at a time, the layout solved again with
// them held, so that the rest adapt before they are rounded in turn.
void round_to_lattice(const BaseSurface& base, SeamlessLayout& layout, int32_t wedges, double unit,
                      double size_hold, const std::array<glm::dvec2, 2>& lattice) {
  const int quarter = 4 / layout.symmetry;
  const std::vector<SeamEdge> edges = seam_edges(base, layout);
  const std::vector<Seam> seams = join_seams(base, layout, edges);
  const auto turn_of = [&](const SeamEdge& e) { return quarter * layout.turn[e.f][e.k]; };
  // The seam's translation in its first edge's orientation (a reversed edge's U_f = R^-1 U_g - R^-1 t).
  const auto mean_translation = [&](const Seam& seam) {
    glm::dvec2 mean(0.0);
    for (size_t n = 0; n < seam.edges.size(); ++n) {
      const SeamEdge& e = edges[seam.edges[n]];
      for (const auto& [from, to] : {std::pair{e.fa, e.ga}, std::pair{e.fb, e.gb}}) {
        const glm::dvec2 t = layout.uv[to] - quarter_turned(layout.uv[from], turn_of(e));
        mean += seam.sides[n] > 0 ? t : -quarter_turned(t, -turn_of(e));
      }
    }
    return mean / (2.0 * static_cast<double>(seam.edges.size()));
  };
  // Distances compared to a millionth of the shorter period, ties by seam: a symmetric base
  // rounds its seams in the same order whatever the floating-point environment.
  const double step = 1e-6 * std::min(glm::length(lattice[0]), glm::length(lattice[1]));
  SeamHold hold;
  hold.translation.assign(base.mesh.num_faces(), {glm::dvec2(0.0), glm::dvec2(0.0), glm::dvec2(0.0)});
  hold.held.assign(base.mesh.num_faces(), {0, 0, 0});
  std::vector<size_t> left(seams.size());
  std::iota(left.begin(), left.end(), size_t{0});
  while (!left.empty()) {
    std::vector<std::pair<double, size_t>> by_distance;
    for (size_t s : left) {
      const glm::dvec2 t = mean_translation(seams[s]);
      by_distance.emplace_back(std::round(glm::distance(t, nearest_period(t, lattice)) / step), s);
    }
    std::sort(by_distance.begin(), by_distance.end());
    const size_t batch = (left.size() + 2) / 3;
    left.clear();
    for (size_t n = 0; n < by_distance.size(); ++n) {
      const size_t s = by_distance[n].second;
      if (n >= batch) {
        left.push_back(s);
        continue;
      }
      const Seam& seam = seams[s];
      const glm::dvec2 period = nearest_period(mean_translation(seam), lattice);
      for (size_t k = 0; k < seam.edges.size(); ++k) {
        const SeamEdge& e = edges[seam.edges[k]];
        hold.translation[e.f][e.k] = seam.sides[k] > 0 ? period : -quarter_turned(period, turn_of(e));
        hold.held[e.f][e.k] = 1;
      }
    }
    solve_layout(base, layout, wedges, unit, size_hold, &hold);
  }
}

}  // namespace

glm::dvec2 quarter_turned(const glm::dvec2& p, int quarter_turns) {
  switch (((quarter_turns % 4) + 4) % 4) {
    case 1: return {-p.y, p.x};
    case 2: return {-p.x, -p.y};
    case 3: return {p.y, -p.x};
    default: return p;
  }
}

SeamlessLayout seamless_layout(const BaseSurface& base, const DirectionField& field,
                               const std::optional<std::array<glm::dvec2, 2>>& lattice, double size_hold,
                               double element_scale) {
  const TriMesh& mesh = base.mesh;
  SeamlessLayout layout;
  layout.symmetry = field.symmetry;
  std::vector<std::array<uint8_t, 3>> tree;
  comb(base, field, layout, tree);
  layout.turn.assign(mesh.num_faces(), {0, 0, 0});
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (g < 0 || tree[f][k]) continue;
      const Vec3 carried = transport_across(base, static_cast<int32_t>(f), g, t[k], t[(k + 1) % 3], layout.axis[f]);
      layout.turn[f][k] = static_cast<int8_t>(
          turn_index(signed_angle(carried, layout.axis[g], base.face_normals[g]), field.symmetry));
    }
  }
  DirectionField combed{field.symmetry, layout.axis};
  const std::vector<int> index = field_indices(base, combed);
  for (size_t v = 0; v < index.size(); ++v)
    if (index[v] != 0) {
      layout.cones.push_back(static_cast<int32_t>(v));
      layout.cone_indices.push_back(index[v]);
    }
  cut_open(base, tree, layout);
  const int32_t wedges = make_wedges(base, layout);
  solve_layout(base, layout, wedges, 1.0, size_hold, nullptr);
  const double scale = normalize_scale(base, layout, lattice.has_value()) * element_scale;
  for (glm::dvec2& p : layout.uv) p /= element_scale;
  if (lattice) {
    round_to_lattice(base, layout, wedges, 1.0 / scale, size_hold, *lattice);
    layout.on_lattice = true;
  }
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (base.face_areas[f] <= 0.0) continue;
    const glm::dvec2 a = layout.uv[layout.corner_wedge[3 * f]], b = layout.uv[layout.corner_wedge[3 * f + 1]],
                     c = layout.uv[layout.corner_wedge[3 * f + 2]];
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) <= 0.0) ++layout.flipped_faces;
  }
  return layout;
}

LayoutWindow unfold_window(const BaseSurface& base, const SeamlessLayout& layout, const std::vector<int32_t>& faces,
                           int32_t start, const std::vector<int32_t>& corner_vertex, int32_t vertices) {
  const TriMesh& mesh = base.mesh;
  const int quarter = 4 / layout.symmetry;
  std::unordered_map<int32_t, int32_t> position;
  for (size_t k = 0; k < faces.size(); ++k) position.emplace(faces[k], static_cast<int32_t>(k));
  LayoutWindow window;
  window.corner_uv.assign(3 * faces.size(), glm::dvec2(0.0));
  std::vector<glm::dvec2> first(static_cast<size_t>(vertices), glm::dvec2(0.0));
  window.face_turn.assign(faces.size(), 0);
  std::vector<glm::dvec2> shift(faces.size(), glm::dvec2(0.0));
  std::vector<uint8_t> reached(faces.size(), 0), placed(static_cast<size_t>(vertices), 0);
  // Window coordinates of a layout point on face k: R(turn) p + shift.
  const auto to_window = [&](size_t k, const glm::dvec2& p) {
    return quarter_turned(p, quarter * window.face_turn[k]) + shift[k];
  };
  double tolerance = 0.0;
  const auto it = position.find(start);
  if (it == position.end()) return window;
  std::deque<int32_t> queue{it->second};
  reached[it->second] = 1;
  while (!queue.empty()) {
    const int32_t k = queue.front();
    queue.pop_front();
    const int32_t f = faces[k];
    const Tri& t = mesh.triangles[f];
    for (int c = 0; c < 3; ++c) {
      const glm::dvec2 p = to_window(k, layout.uv[layout.corner_wedge[3 * f + c]]);
      const int32_t local = corner_vertex[3 * k + c];
      window.corner_uv[3 * k + c] = p;
      tolerance = std::max(tolerance, 1e-6 * glm::length(mesh.positions[t[c]] - mesh.positions[t[(c + 1) % 3]]));
      if (!placed[local]) {
        placed[local] = 1;
        first[local] = p;
      } else if (glm::length(first[local] - p) > tolerance) {
        window.consistent = false;
      }
    }
    for (int e = 0; e < 3; ++e) {
      const auto across = position.find(base.face_across[f][e]);
      if (base.face_across[f][e] < 0 || across == position.end() || reached[across->second]) continue;
      const int32_t j = across->second, g = faces[j];
      reached[j] = 1;
      window.face_turn[j] = (window.face_turn[k] + layout.turn[f][e]) % layout.symmetry;
      // Through the shared corner a: the point keeps its window position.
      const int32_t a = t[e];
      const glm::dvec2 here = to_window(k, layout.uv[layout.corner_wedge[3 * f + e]]);
      const glm::dvec2 there = layout.uv[layout.corner_wedge[3 * g + corner_of(mesh.triangles[g], a)]];
      shift[j] = here - quarter_turned(there, quarter * window.face_turn[j]);
      queue.push_back(j);
    }
  }
  return window;
}

}  // namespace meshquilt
