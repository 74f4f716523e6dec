#include "quilt/element_deformation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "support/bumpy_sphere.h"

namespace meshquilt {
namespace {

TriMesh sphere(int rings, int segments, double radius, Vec3 centre, uint32_t seed) {
  return test::bumpy_sphere(rings, segments, radius, centre, seed, 0.05);
}

// An open n x n grid patch with a bumpy height.
TriMesh grid(int n) {
  TriMesh m;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) m.positions.emplace_back(x * 0.3, y * 0.25, 0.1 * std::sin(x + 2.0 * y));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

double max_error(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  EXPECT_EQ(a.size(), b.size());
  double e = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) e = std::max(e, glm::length(a[i] - b[i]));
  return e;
}

// Independent reference: the stacked least-squares system of Eq. 5/6 over all vertices, built
// densely from the 1-ring sets and solved with Householder QR.
struct DenseRow {
  std::vector<std::pair<int, double>> terms;
  Vec3 target;
};
std::vector<Vec3> dense_reference(const TriMesh& m, const std::vector<DenseRow>& cons, double mu) {
  const int n = int(m.positions.size());
  std::vector<std::set<int>> ring(n);
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      ring[t[k]].insert(t[(k + 1) % 3]);
      ring[t[k]].insert(t[(k + 2) % 3]);
    }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + cons.size(), n);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n + cons.size(), 3);
  for (int i = 0; i < n; ++i) {
    A(i, i) = 1;
    for (int j : ring[i]) A(i, j) -= 1.0 / ring[i].size();
  }
  Eigen::MatrixXd P(n, 3);
  for (int i = 0; i < n; ++i) P.row(i) << m.positions[i].x, m.positions[i].y, m.positions[i].z;
  b.topRows(n) = A.topRows(n) * P;  // the original Laplacian coordinates
  const double s = std::sqrt(mu);
  for (size_t c = 0; c < cons.size(); ++c) {
    for (auto [v, w] : cons[c].terms) A(n + c, v) += s * w;
    b.row(n + c) << s * cons[c].target.x, s * cons[c].target.y, s * cons[c].target.z;
  }
  const Eigen::MatrixXd X = A.colPivHouseholderQr().solve(b);
  std::vector<Vec3> out(n);
  for (int i = 0; i < n; ++i) out[i] = Vec3(X(i, 0), X(i, 1), X(i, 2));
  return out;
}

TEST(ElementDeformation, NoConstraintsKeepsPositionsExactly) {
  const TriMesh m = sphere(5, 8, 1.0, Vec3(0.2, -0.1, 0.4), 1);
  EXPECT_EQ(deform_with_vertex_constraints(m, {}), m.positions);
  EXPECT_EQ(deform_with_face_constraints(m, {}), m.positions);
}

TEST(ElementDeformation, ConstraintsAtCurrentPositionsKeepPositions) {
  const TriMesh m = sphere(6, 9, 1.0, Vec3(0.0), 2);
  std::vector<VertexConstraint> vc;
  for (int v : {0, 5, 17, 30}) vc.push_back({v, m.positions[v]});
  EXPECT_LE(max_error(deform_with_vertex_constraints(m, vc), m.positions), 1e-12);
  std::vector<FaceConstraint> fc;
  for (int f : {0, 11, 40}) {
    const Vec3 bary(0.2, 0.5, 0.3);
    const Tri& t = m.triangles[f];
    fc.push_back({f, bary, bary.x * m.positions[t[0]] + bary.y * m.positions[t[1]] + bary.z * m.positions[t[2]]});
  }
  EXPECT_LE(max_error(deform_with_face_constraints(m, fc), m.positions), 1e-12);
}

TEST(ElementDeformation, SingleVertexConstraintTranslatesRigidly) {
  // Eq. 5 with one constraint: a translation keeps every Laplacian coordinate and meets the
  // constraint, so it is the (unique) minimizer with zero energy.
  for (const TriMesh& m : {sphere(5, 7, 2.0, Vec3(1, 2, 3), 3), grid(6)}) {
    const int v = 9;
    const Vec3 target = m.positions[v] + Vec3(0.3, -0.7, 0.25);
    const std::vector<Vec3> w = deform_with_vertex_constraints(m, {{v, target}});
    std::vector<Vec3> expected = m.positions;
    for (Vec3& p : expected) p += target - m.positions[v];
    EXPECT_LE(max_error(w, expected), 1e-9);
  }
}

TEST(ElementDeformation, SingleFaceConstraintTranslatesRigidly) {
  const TriMesh m = sphere(5, 7, 1.0, Vec3(0.0), 4);
  const int f = 13;
  const Vec3 bary(0.1, 0.6, 0.3);
  const Tri& t = m.triangles[f];
  const Vec3 h = bary.x * m.positions[t[0]] + bary.y * m.positions[t[1]] + bary.z * m.positions[t[2]];
  const Vec3 target = h + Vec3(-0.2, 0.1, 0.4);
  const std::vector<Vec3> w = deform_with_face_constraints(m, {{f, bary, target}});
  for (size_t i = 0; i < w.size(); ++i) EXPECT_LE(glm::length(w[i] - (m.positions[i] + target - h)), 1e-9);
}

TEST(ElementDeformation, MatchesDenseLeastSquaresWithVertexConstraints) {
  const TriMesh m = grid(5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<VertexConstraint> vc;
  std::vector<DenseRow> rows;
  // Several vertices, one of them constrained twice (an element with two partners).
  for (int v : {0, 7, 7, 20, 35}) {
    const Vec3 target = m.positions[v] + Vec3(u(rng), u(rng), u(rng));
    vc.push_back({v, target});
    rows.push_back({{{v, 1.0}}, target});
  }
  for (double mu : {1.0, 0.25, 10.0}) {
    const std::vector<Vec3> w = deform_with_vertex_constraints(m, vc, {mu});
    EXPECT_LE(max_error(w, dense_reference(m, rows, mu)), 1e-9) << "mu " << mu;
    // The constraints actually move the element.
    EXPECT_GT(max_error(w, m.positions), 1e-2);
  }
}

TEST(ElementDeformation, MatchesDenseLeastSquaresWithFaceConstraints) {
  const TriMesh m = sphere(4, 6, 1.0, Vec3(0.5, 0.5, 0.0), 8);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.2, 0.2), b(0.05, 1.0);
  std::vector<FaceConstraint> fc;
  std::vector<DenseRow> rows;
  for (int f : {0, 3, 9, 17, 22, 30}) {
    Vec3 bary(b(rng), b(rng), b(rng));
    bary /= bary.x + bary.y + bary.z;
    const Tri& t = m.triangles[f];
    const Vec3 h = bary.x * m.positions[t[0]] + bary.y * m.positions[t[1]] + bary.z * m.positions[t[2]];
    const Vec3 target = h + Vec3(u(rng), u(rng), u(rng));
    fc.push_back({f, bary, target});
    rows.push_back({{{t[0], bary.x}, {t[1], bary.y}, {t[2], bary.z}}, target});
  }
  const std::vector<Vec3> w = deform_with_face_constraints(m, fc);
  EXPECT_LE(max_error(w, dense_reference(m, rows, 1.0)), 1e-9);
  EXPECT_GT(max_error(w, m.positions), 1e-2);
}

// Solves reuse the fill-reducing ordering of an earlier system with the same sparsity pattern
// (per thread). Reused or not, the positions must be the same bit for bit; a pattern of the
// same size but other connections (the grid with its vertices renumbered) must not be given
// another's ordering, nor must a pattern pushed out of the cache and met again.
TEST(ElementDeformation, RepeatedPatternsSolveAsFreshOnes) {
  const TriMesh base = grid(6);
  TriMesh renumbered = base;
  std::vector<int32_t> to(base.num_vertices());
  for (size_t v = 0; v < to.size(); ++v) to[v] = static_cast<int32_t>((v * 17) % to.size());  // 49 vertices, 17 coprime
  for (size_t v = 0; v < to.size(); ++v) renumbered.positions[to[v]] = base.positions[v];
  for (Tri& t : renumbered.triangles)
    for (int32_t& v : t) v = to[v];
  const std::vector<VertexConstraint> cons = {{0, Vec3(0.1, -0.2, 0.3)}, {24, Vec3(1.0, 0.9, -0.2)}, {48, Vec3(1.9, 1.4, 0.4)}};
  std::vector<VertexConstraint> renumbered_cons = cons;
  for (VertexConstraint& c : renumbered_cons) c.vertex = to[c.vertex];
  // Grids of other sizes, enough to push both patterns out of the cache.
  std::vector<TriMesh> others;
  for (int n = 2; n < 14; ++n) others.push_back(grid(n));

  const auto fresh = [](const TriMesh& m, const std::vector<VertexConstraint>& c) {
    std::vector<Vec3> w;
    std::thread([&] { w = deform_with_vertex_constraints(m, c); }).join();
    return w;
  };
  const std::vector<Vec3> expected = fresh(base, cons);
  const std::vector<Vec3> expected_renumbered = fresh(renumbered, renumbered_cons);
  EXPECT_GT(max_error(expected, base.positions), 1e-2);
  for (int round = 0; round < 3; ++round) {
    EXPECT_EQ(deform_with_vertex_constraints(base, cons), expected) << "round " << round;
    EXPECT_EQ(deform_with_vertex_constraints(renumbered, renumbered_cons), expected_renumbered) << "round " << round;
    EXPECT_EQ(deform_with_vertex_constraints(base, cons), expected) << "round " << round;
    if (round == 1)
      for (const TriMesh& m : others) deform_with_vertex_constraints(m, {{0, Vec3(0.0, 0.0, 1.0)}});
  }
  // The renumbered grid's solution is the base's, renumbered (to rounding).
  for (size_t v = 0; v < to.size(); ++v) EXPECT_LE(glm::length(expected_renumbered[to[v]] - expected[v]), 1e-9);
}

TEST(ElementDeformation, UnconstrainedPartsAndIsolatedVerticesStay) {
  // Two spheres in one mesh plus an unreferenced vertex: only the constrained sphere moves.
  TriMesh a = sphere(4, 6, 1.0, Vec3(0.0), 5);
  const TriMesh b = sphere(3, 5, 0.5, Vec3(4, 0, 0), 6);
  const int offset = int(a.positions.size());
  for (const Vec3& p : b.positions) a.positions.push_back(p);
  for (Tri t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  a.positions.emplace_back(9, 9, 9);
  const int isolated = int(a.positions.size()) - 1;
  const Vec3 shift(0.5, 0.0, -0.5);
  const std::vector<Vec3> w =
      deform_with_vertex_constraints(a, {{2, a.positions[2] + shift}, {isolated, Vec3(0.0)}});
  for (int i = 0; i < offset; ++i) EXPECT_LE(glm::length(w[i] - (a.positions[i] + shift)), 1e-9);
  for (int i = offset; i < isolated; ++i) EXPECT_EQ(w[i], a.positions[i]);
  EXPECT_EQ(w[isolated], a.positions[isolated]);
}

TEST(ElementDeformation, RejectsBadInput) {
  const TriMesh m = grid(2);
  EXPECT_THROW(deform_with_vertex_constraints(m, {{99, Vec3(0.0)}}), std::out_of_range);
  EXPECT_THROW(deform_with_face_constraints(m, {{-1, Vec3(1, 0, 0), Vec3(0.0)}}), std::out_of_range);
  EXPECT_THROW(deform_with_vertex_constraints(m, {{0, Vec3(0.0)}}, {0.0}), InputError);
  EXPECT_THROW(deform_with_vertex_constraints(m, {{0, Vec3(NAN, 0, 0)}}), InputError);
  // Barycentrics summing to zero cannot pin the element's translation.
  EXPECT_THROW(deform_with_face_constraints(m, {{0, Vec3(1, -1, 0), Vec3(0.1)}}), SolverError);
}

// Optimality of a Eq. 5 solution without any solver: the gradient
// L^T (L w - L v) + mu sum_c (w_c - t_c) vanishes, computed here with plain loops.
double gradient_norm(const TriMesh& m, const std::vector<Vec3>& w, const std::vector<VertexConstraint>& cons,
                     double mu) {
  const size_t n = m.positions.size();
  std::vector<std::set<int>> ring(n);
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) ring[t[k]].insert(t[(k + 1) % 3]), ring[t[k]].insert(t[(k + 2) % 3]);
  auto lap = [&](const std::vector<Vec3>& x, size_t i) {
    Vec3 mean(0.0);
    for (int j : ring[i]) mean += x[j];
    return x[i] - mean / double(ring[i].size());
  };
  std::vector<Vec3> r(n), g(n, Vec3(0.0));
  for (size_t i = 0; i < n; ++i) r[i] = lap(w, i) - lap(m.positions, i);
  for (size_t i = 0; i < n; ++i) {  // g = L^T r
    g[i] += r[i];
    for (int j : ring[i]) g[j] -= r[i] / double(ring[i].size());
  }
  for (const VertexConstraint& c : cons) g[c.vertex] += mu * (w[c.vertex] - c.target);
  double norm = 0;
  for (const Vec3& v : g) norm = std::max(norm, glm::length(v));
  return norm;
}

TEST(ElementDeformation, RealMeshTranslationAndOptimality) {
  const std::filesystem::path file = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes/knot.off";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const TriMesh m = read_mesh(file);
  // One constraint: a rigid translation (Eq. 5 energy zero).
  const Vec3 shift(0.01, -0.02, 0.03);
  const std::vector<Vec3> w = deform_with_vertex_constraints(m, {{100, m.positions[100] + shift}});
  for (size_t i = 0; i < w.size(); ++i) ASSERT_LE(glm::length(w[i] - m.positions[i] - shift), 1e-7) << i;
  // Many constraints: the result zeroes the energy's gradient, and it moved.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<VertexConstraint> cons;
  for (int k = 0; k < 60; ++k) {
    const int v = int(rng() % m.positions.size());
    cons.push_back({v, m.positions[v] + Vec3(u(rng), u(rng), u(rng))});
  }
  const std::vector<Vec3> x = deform_with_vertex_constraints(m, cons);
  EXPECT_LE(gradient_norm(m, x, cons, 1.0), 1e-9);
  EXPECT_GT(max_error(x, m.positions), 1e-3);
}

}  // namespace
}  // namespace meshquilt
