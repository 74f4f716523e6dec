#include "surface/cone_metric_field.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <deque>
#include <initializer_list>
#include <glm/geometric.hpp>
#include <limits>

#include "core/constants.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "numerics/sparse_solve.h"

namespace meshquilt {
namespace {

// Rounds of moving each placed cone to where the others leave the scale lowest; a new placement
// is kept where it narrows the scale's spread by this factor.
constexpr int kSettleRounds = 8;
constexpr double kRelocationGain = 0.995;

double corner_angle(const TriMesh& mesh, const Tri& t, int k) {
  const Vec3 a = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
  const Vec3 b = mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[k]];
  const double la = glm::length(a), lb = glm::length(b);
  if (la <= 0.0 || lb <= 0.0) return 0.0;
  return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

std::vector<double> angle_defects(const TriMesh& mesh) {
  std::vector<double> defect(mesh.num_vertices(), 2.0 * kPi);
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) defect[t[k]] -= corner_angle(mesh, t, k);
  return defect;
}

// The bases the cone metric takes: one closed component of genus 0, or one disc, whose border
// keeps the base's own lengths (phi = 0 there) and takes what curvature the cones leave.
enum class MetricShape { kNone, kSphere, kDisc };

MetricShape metric_shape(const BaseSurface& base) {
  const SurfaceReport r = inspect_surface(base.mesh);
  if (r.components != 1 || r.nonmanifold_edges != 0 || r.misoriented_edges != 0 || r.pinched_vertices != 0 ||
      r.degenerate_faces != 0)
    return MetricShape::kNone;
  if (r.boundary_edges == 0 && r.euler == 2) return MetricShape::kSphere;
  if (r.boundary_edges > 0 && r.euler == 1) return MetricShape::kDisc;
  return MetricShape::kNone;
}

std::vector<uint8_t> border_vertices(const BaseSurface& base) {
  std::vector<uint8_t> border(base.mesh.num_vertices(), 0);
  for (size_t f = 0; f < base.mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (base.face_across[f][k] < 0) border[base.mesh.triangles[f][k]] = border[base.mesh.triangles[f][(k + 1) % 3]] = 1;
  return border;
}

// The cotan Laplacian of a closed base or a disc, factored once for every curvature asked of it.
class ConeMetric {
 public:
  //! border: per vertex, 1 where phi is held at 0 (a disc's border); empty for a closed base.
  ConeMetric(const BaseSurface& base, std::vector<uint8_t> border)
      : defect_(angle_defects(base.mesh)), border_(std::move(border)),
        factor_(laplacian(base.mesh, border_), "cone metric") {}

  //! phi solving L phi = K_hat - K: mean 0 over a closed base, 0 on a disc's border.
  std::vector<double> scale(const std::vector<double>& target_curvature) const {
    const auto n = static_cast<Eigen::Index>(defect_.size());
    Eigen::MatrixXd rhs(n, 1);
    for (Eigen::Index v = 0; v < n; ++v)
      rhs(v, 0) = !border_.empty() && border_[v] ? 0.0 : target_curvature[v] - defect_[v];
    const Eigen::MatrixXd phi = factor_.solve(rhs);
    std::vector<double> result(static_cast<size_t>(n));
    double mean = 0.0;
    for (Eigen::Index v = 0; v < n; ++v) mean += (result[v] = phi(v, 0)) / static_cast<double>(n);
    if (border_.empty())
      for (double& x : result) x -= mean;
    return result;
  }

 private:
  static Eigen::SparseMatrix<double> laplacian(const TriMesh& mesh, const std::vector<uint8_t>& border) {
    const auto n = static_cast<Eigen::Index>(mesh.num_vertices());
    std::vector<Eigen::Triplet<double>> triplets;
    double largest = 0.0;
    for (const Tri& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const double w = half_cotangent(mesh, t, k);
        const int32_t i = t[(k + 1) % 3], j = t[(k + 2) % 3];
        const bool held_i = !border.empty() && border[i], held_j = !border.empty() && border[j];
        // A held vertex's phi is 0: its row is the identity and its column drops out.
        if (!held_i) triplets.emplace_back(i, i, w);
        if (!held_j) triplets.emplace_back(j, j, w);
        if (!held_i && !held_j) {
          triplets.emplace_back(i, j, -w);
          triplets.emplace_back(j, i, -w);
        }
        largest = std::max(largest, std::abs(w));
      }
    for (Eigen::Index v = 0; v < n; ++v)
      if (!border.empty() && border[v]) triplets.emplace_back(v, v, 1.0);
    // Over a closed base phi is defined up to a constant: a faint pull to 0 picks one, the mean
    // taken out after.
    for (Eigen::Index v = 0; v < n; ++v) triplets.emplace_back(v, v, 1e-9 * std::max(largest, 1e-300));
    Eigen::SparseMatrix<double> L(n, n);
    L.setFromTriplets(triplets.begin(), triplets.end());
    return L;
  }

  std::vector<double> defect_;
  std::vector<uint8_t> border_;
  PositiveDefiniteFactor factor_;
};

}  // namespace

std::vector<double> cone_metric_scale(const BaseSurface& base, const std::vector<double>& target_curvature) {
  return ConeMetric(base, metric_shape(base) == MetricShape::kDisc ? border_vertices(base) : std::vector<uint8_t>{})
      .scale(target_curvature);
}

double scale_spread(const BaseSurface& base, const std::vector<double>& phi) {
  const TriMesh& mesh = base.mesh;
  std::vector<std::pair<double, double>> scales;  // (phi, vertex area)
  double total = 0.0;
  std::vector<double> area(mesh.num_vertices(), 0.0);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f]) area[v] += base.face_areas[f] / 3.0;
  for (size_t v = 0; v < phi.size(); ++v) {
    scales.emplace_back(phi[v], area[v]);
    total += area[v];
  }
  if (scales.empty() || !(total > 0.0)) return 1.0;
  std::sort(scales.begin(), scales.end());
  const auto quantile = [&](double q) {
    double below = 0.0;
    for (const auto& [value, weight] : scales)
      if ((below += weight) >= q * total) return value;
    return scales.back().first;
  };
  return std::exp(quantile(0.9) - quantile(0.1));
}

std::optional<double> cone_scale_spread(const BaseSurface& base, const std::vector<int>& index, int symmetry) {
  if (metric_shape(base) == MetricShape::kNone) return std::nullopt;
  std::vector<double> curvature(index.size());
  for (size_t v = 0; v < index.size(); ++v) curvature[v] = index[v] * 2.0 * kPi / symmetry;
  return scale_spread(base, cone_metric_scale(base, curvature));
}

std::optional<double> field_scale_spread(const BaseSurface& base, const DirectionField& field) {
  return cone_scale_spread(base, field_indices(base, field), field.symmetry);
}

std::optional<DirectionField> cone_metric_field(const BaseSurface& base, int symmetry, const Vec3& root_direction,
                                                const ConeBound& bound) {
  const MetricShape shape = metric_shape(base);
  if (shape == MetricShape::kNone) return std::nullopt;
  const std::vector<uint8_t> border =
      shape == MetricShape::kDisc ? border_vertices(base) : std::vector<uint8_t>(base.mesh.num_vertices(), 0);
  const TriMesh& mesh = base.mesh;
  const size_t vertices = mesh.num_vertices();
  std::vector<double> vertex_area(vertices, 0.0);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t v : mesh.triangles[f]) vertex_area[v] += base.face_areas[f] / 3.0;
  const double deficit = 2.0 * kPi / symmetry;  // of one cone of index 1 / n
  // On a sphere 2n cones whose deficits sum to 2 pi x 2; a disc's border takes what its cones leave.
  const int count = shape == MetricShape::kSphere ? 2 * symmetry : 0;
  std::vector<int32_t> negative;  // cones of index -1 / n
  // The curvature asked for: the cones', and on a sphere what is left spread by area.
  const auto target = [&](const std::vector<int32_t>& cones) {
    const double left = shape == MetricShape::kDisc ? 0.0
                                                    : 4.0 * kPi - deficit * (static_cast<double>(cones.size()) -
                                                                             static_cast<double>(negative.size()));
    std::vector<double> k(vertices);
    for (size_t v = 0; v < vertices; ++v) k[v] = left * vertex_area[v] / base.area;
    for (int32_t c : cones) k[c] += deficit;
    for (int32_t c : negative) k[c] -= deficit;
    return k;
  };
  // The vertex off the border where `of` is lowest (or highest), none of `taken`, at least
  // `bound.separation` from each of them; where none is that far, the nearer ones when
  // `or_nearer`, else -1.
  const auto pick = [&](const std::vector<double>& of, bool highest, std::initializer_list<const std::vector<int32_t>*> taken,
                        bool or_nearer) {
    int32_t best = -1, nearer = -1;
    const auto better = [&](size_t v, int32_t than) { return than < 0 || (highest ? of[v] > of[than] : of[v] < of[than]); };
    for (size_t v = 0; v < vertices; ++v) {
      if (base.vertex_faces[v].empty() || border[v]) continue;
      bool is_taken = false, apart = true;
      for (const std::vector<int32_t>* set : taken)
        for (int32_t c : *set) {
          is_taken = is_taken || c == static_cast<int32_t>(v);
          apart = apart && glm::length(mesh.positions[c] - mesh.positions[v]) >= bound.separation;
        }
      if (is_taken) continue;
      int32_t& slot = apart ? best : nearer;
      if (better(v, slot)) slot = static_cast<int32_t>(v);
    }
    return best >= 0 || !or_nearer ? best : nearer;
  };
  const auto lowest = [&](const std::vector<double>& phi, const std::vector<int32_t>& taken) {
    return pick(phi, false, {&taken}, true);
  };
  const ConeMetric metric(base, shape == MetricShape::kDisc ? border : std::vector<uint8_t>{});
  std::vector<int32_t> cones;
  while (static_cast<int>(cones.size()) < count)
    cones.push_back(lowest(metric.scale(target(cones)), cones));
  std::vector<double> phi = metric.scale(target(cones));
  // Greedy placement can end balanced but uneven, as a square on a sphere's great circle, which
  // no single cone's move leaves. So: two cones taken out and put back greedily, then each cone
  // in turn moved to where the others leave the scale lowest until none moves; kept where that
  // evens the scale (the square opens to a tetrahedron).
  double spread = scale_spread(base, phi);
  const auto settle = [&](std::vector<int32_t> at) {
    for (int round = 0; round < kSettleRounds; ++round) {
      bool moved = false;
      for (size_t i = 0; i < at.size(); ++i) {
        std::vector<int32_t> rest = at;
        rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
        const int32_t v = lowest(metric.scale(target(rest)), rest);
        moved = moved || v != at[i];
        at[i] = v;
      }
      if (!moved) break;
    }
    return at;
  };
  for (size_t i = 0; i < cones.size(); ++i)
    for (size_t j = i + 1; j < cones.size(); ++j) {
      std::vector<int32_t> rest;
      for (size_t k = 0; k < cones.size(); ++k)
        if (k != i && k != j) rest.push_back(cones[k]);
      while (rest.size() < cones.size()) rest.push_back(lowest(metric.scale(target(rest)), rest));
      std::vector<int32_t> tried = settle(std::move(rest));
      std::vector<double> tried_phi = metric.scale(target(tried));
      const double tried_spread = scale_spread(base, tried_phi);
      if (!(tried_spread < kRelocationGain * spread)) continue;
      cones = std::move(tried);
      phi = std::move(tried_phi);
      spread = tried_spread;
    }

  // Cones where the scale runs away, while the spread is above the bound: on a sphere in pairs,
  // a negative cone where lengths in the metric are longest (elements smallest), then a positive
  // one where they are shortest; on a disc one at a time, of the sign that evens the scale more.
  // Each apart from every cone so far.
  const auto extreme = [&](const std::vector<double>& of, bool highest) {
    return pick(of, highest, {&cones, &negative}, false);
  };
  // The greedy cones do not narrow the spread step by step: the placement kept is the first
  // within the bound, or else the narrowest seen.
  std::vector<int32_t> best_cones = cones, best_negative = negative;
  double best_spread = spread;
  const int steps = shape == MetricShape::kDisc ? 2 * bound.max_pairs : bound.max_pairs;
  for (int step = 0; step < steps && best_spread > bound.spread; ++step) {
    const int32_t high = extreme(phi, true);
    if (high < 0) break;
    negative.push_back(high);
    if (shape == MetricShape::kDisc) {
      std::vector<double> with_negative = metric.scale(target(cones));
      const double negative_spread = scale_spread(base, with_negative);
      negative.pop_back();
      const int32_t low = extreme(phi, false);
      if (low >= 0) {
        cones.push_back(low);
        phi = metric.scale(target(cones));
        spread = scale_spread(base, phi);
      }
      if (low < 0 || negative_spread < spread) {
        if (low >= 0) cones.pop_back();
        negative.push_back(high);
        phi = std::move(with_negative);
        spread = negative_spread;
      }
    } else {
      const int32_t low = extreme(metric.scale(target(cones)), false);
      if (low < 0) break;
      cones.push_back(low);
      phi = metric.scale(target(cones));
      spread = scale_spread(base, phi);
    }
    if (spread < kRelocationGain * best_spread) {
      best_cones = cones;
      best_negative = negative;
      best_spread = spread;
    }
  }
  cones = std::move(best_cones);
  negative = std::move(best_negative);
  phi = metric.scale(target(cones));

  // Parallel transport in the scaled metric: the surface's own across each edge, turned by the
  // metric's rotation, minus the cotan-weighted change of phi along the edge.
  DirectionField field;
  field.symmetry = symmetry;
  field.directions.assign(mesh.num_faces(), Vec3(0.0));
  std::vector<uint8_t> reached(mesh.num_faces(), 0);
  const Vec3 n0 = base.face_normals[0];
  Vec3 d = root_direction - glm::dot(root_direction, n0) * n0;
  if (!(glm::length(d) > 1e-12))
    d = mesh.positions[mesh.triangles[0][1]] - mesh.positions[mesh.triangles[0][0]];
  field.directions[0] = glm::normalize(d);
  reached[0] = 1;
  std::deque<int32_t> queue{0};
  while (!queue.empty()) {
    const int32_t f = queue.front();
    queue.pop_front();
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (g < 0 || reached[g]) continue;
      reached[g] = 1;
      const int32_t a = t[k], b = t[(k + 1) % 3];
      const Tri& tg = mesh.triangles[g];
      const int kg = tg[0] == b ? 0 : tg[1] == b ? 1 : 2;  // g's edge (b, a) and its opposite corner
      const double w = half_cotangent(mesh, t, (k + 2) % 3) + half_cotangent(mesh, tg, (kg + 2) % 3);
      const double turn = w * (phi[b] - phi[a]);
      const Vec3 carried = transport_across(base, f, g, a, b, field.directions[f]);
      const Vec3 n = base.face_normals[g];
      field.directions[g] =
          glm::normalize(std::cos(turn) * carried + std::sin(turn) * glm::cross(n, carried));
      queue.push_back(g);
    }
  }
  return field;
}

}  // namespace meshquilt
