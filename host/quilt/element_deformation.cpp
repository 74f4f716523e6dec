#include "quilt/element_deformation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Sparse>

#include "core/error.h"
#include "numerics/sparse_solve.h"
#include "mesh/disjoint_sets.h"

namespace meshquilt {
namespace {

//! One position constraint of Eq. 5/6: sum_k weight[k] * w_{vertex[k]} at `target`.
struct ConstraintRow {
  int32_t vertex[3];
  double weight[3];
  int count;
  Vec3 target;
};

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

//! Uniform 1-ring (Eq. 4) in compressed rows: neighbours of v are ring[offsets[v] .. offsets[v+1]).
struct OneRing {
  std::vector<int32_t> offsets;
  std::vector<int32_t> ring;
};

OneRing one_ring(const TriMesh& mesh) {
  const int32_t nv = static_cast<int32_t>(mesh.num_vertices());
  // Each edge's two directions bucketed by their first vertex, then each bucket sorted and
  // deduplicated: small sorts instead of one over all 6F directed edges.
  std::vector<int32_t> first(nv + 1, 0);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      if (a < 0 || a >= nv || b < 0 || b >= nv) {
        throw InputError("element deformation: face " + std::to_string(f) + " has a vertex index outside [0, " +
                         std::to_string(nv) + ")");
      }
      if (a == b) continue;
      ++first[a + 1];
      ++first[b + 1];
    }
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<int32_t> all(first[nv]);
  std::vector<int32_t> fill(first.begin(), first.end() - 1);
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      if (a == b) continue;
      all[fill[a]++] = b;
      all[fill[b]++] = a;
    }
  OneRing r;
  r.offsets.assign(nv + 1, 0);
  r.ring.reserve(all.size() / 2);
  for (int32_t v = 0; v < nv; ++v) {
    const auto begin = all.begin() + first[v], end = all.begin() + first[v + 1];
    std::sort(begin, end);
    r.ring.insert(r.ring.end(), begin, std::unique(begin, end));
    r.offsets[v + 1] = static_cast<int32_t>(r.ring.size());
  }
  return r;
}

//! Minimizes sum_i |L(w_i) - L(v_i)|^2 + mu sum_rows |sum_k a_k w_k - c|^2 (Eq. 5 and 6 share it).
std::vector<Vec3> solve_deformation(const TriMesh& mesh, const std::vector<ConstraintRow>& rows, double mu) {
  if (!(mu > 0.0) || !std::isfinite(mu)) {
    throw InputError("element deformation: mu = " + std::to_string(mu) + " must be positive and finite",
                     ErrorKind::invalid_option);
  }
  std::vector<Vec3> result = mesh.positions;
  if (rows.empty()) return result;

  const int32_t nv = static_cast<int32_t>(mesh.num_vertices());
  const OneRing ring = one_ring(mesh);
  auto degree = [&](int32_t v) { return ring.offsets[v + 1] - ring.offsets[v]; };

  // Parts of the element no constraint reaches have a translation as null space: keep them fixed
  // (their original positions have zero energy) and solve only the constrained parts.
  DisjointSets pieces(nv);
  for (int32_t v = 0; v < nv; ++v) {
    for (int32_t k = ring.offsets[v]; k < ring.offsets[v + 1]; ++k) {
      pieces.unite(v, ring.ring[k]);
    }
  }
  std::vector<uint8_t> constrained_root(nv, 0);
  for (const ConstraintRow& row : rows) {
    for (int k = 0; k < row.count; ++k) {
      if (row.weight[k] != 0.0 && degree(row.vertex[k]) > 0) constrained_root[pieces.find(row.vertex[k])] = 1;
    }
  }
  std::vector<int32_t> unknown(nv, -1);
  int32_t m = 0;
  for (int32_t v = 0; v < nv; ++v) {
    if (degree(v) > 0 && constrained_root[pieces.find(v)]) unknown[v] = m++;
  }
  if (m == 0) return result;

  // Unknowns are displacements d = w - v: L d = 0 keeps the Laplacian coordinates, and constraints
  // already met give an exactly zero right-hand side (hence exactly unchanged positions).
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> lap;
  lap.reserve(m + ring.ring.size());
  for (int32_t v = 0; v < nv; ++v) {
    const int32_t i = unknown[v];
    if (i < 0) continue;
    const double w = -1.0 / degree(v);
    lap.emplace_back(i, i, 1.0);
    for (int32_t k = ring.offsets[v]; k < ring.offsets[v + 1]; ++k) lap.emplace_back(i, unknown[ring.ring[k]], w);
  }
  Eigen::SparseMatrix<double> L(m, m);
  L.setFromTriplets(lap.begin(), lap.end());

  std::vector<Triplet> cons;
  cons.reserve(rows.size() * 3);
  Eigen::MatrixX3d residual(rows.size(), 3);
  int32_t nrows = 0;
  for (const ConstraintRow& row : rows) {
    Vec3 r = row.target;
    bool any = false;
    for (int k = 0; k < row.count; ++k) {
      r -= row.weight[k] * mesh.positions[row.vertex[k]];
      const int32_t i = unknown[row.vertex[k]];
      if (i >= 0 && row.weight[k] != 0.0) {
        cons.emplace_back(nrows, i, row.weight[k]);
        any = true;
      }
    }
    if (!any) continue;  // touches only fixed vertices: a constant term of the energy
    residual.row(nrows) << r.x, r.y, r.z;
    ++nrows;
  }
  Eigen::SparseMatrix<double> C(nrows, m);
  C.setFromTriplets(cons.begin(), cons.end());

  const Eigen::SparseMatrix<double> Lt = L.transpose();
  const Eigen::SparseMatrix<double> Ct = C.transpose();
  Eigen::SparseMatrix<double> A = Lt * L;
  A += mu * (Ct * C);
  const Eigen::MatrixX3d rhs = mu * (Ct * residual.topRows(nrows));

  // A semi-definite system (a constrained part whose constraints cannot pin its translation) is
  // refused as singular. The copies of one swatch element share a pattern: orderings are reused.
  const Eigen::MatrixXd d = solve_positive_definite(
      A, rhs, "element deformation: the " + std::to_string(m) + "-vertex Laplacian system",
      SolveOptions{SolveOrdering::amd_cached, /*refuse_singular=*/true});
  for (int32_t v = 0; v < nv; ++v) {
    const int32_t i = unknown[v];
    if (i >= 0) result[v] += Vec3(d(i, 0), d(i, 1), d(i, 2));
  }
  return result;
}

}  // namespace

std::vector<Vec3> deform_with_vertex_constraints(const TriMesh& element,
                                                 const std::vector<VertexConstraint>& constraints,
                                                 const DeformationOptions& options) {
  std::vector<ConstraintRow> rows;
  rows.reserve(constraints.size());
  const int32_t nv = static_cast<int32_t>(element.num_vertices());
  for (size_t c = 0; c < constraints.size(); ++c) {
    const VertexConstraint& vc = constraints[c];
    if (vc.vertex < 0 || vc.vertex >= nv) {
      throw std::out_of_range("element deformation: constraint " + std::to_string(c) + " names vertex " +
                              std::to_string(vc.vertex) + " outside [0, " + std::to_string(nv) + ")");
    }
    if (!finite(vc.target)) {
      throw InputError("element deformation: constraint " + std::to_string(c) + " has a non-finite target",
                       ErrorKind::invalid_option);
    }
    rows.push_back(ConstraintRow{{vc.vertex, 0, 0}, {1.0, 0.0, 0.0}, 1, vc.target});
  }
  return solve_deformation(element, rows, options.mu);
}

std::vector<Vec3> deform_with_face_constraints(const TriMesh& element,
                                               const std::vector<FaceConstraint>& constraints,
                                               const DeformationOptions& options) {
  std::vector<ConstraintRow> rows;
  rows.reserve(constraints.size());
  const int32_t nf = static_cast<int32_t>(element.num_faces());
  const int32_t nv = static_cast<int32_t>(element.num_vertices());
  for (size_t c = 0; c < constraints.size(); ++c) {
    const FaceConstraint& fc = constraints[c];
    if (fc.face < 0 || fc.face >= nf) {
      throw std::out_of_range("element deformation: constraint " + std::to_string(c) + " names face " +
                              std::to_string(fc.face) + " outside [0, " + std::to_string(nf) + ")");
    }
    if (!finite(fc.target) || !finite(fc.barycentric)) {
      throw InputError("element deformation: face constraint " + std::to_string(c) + " has non-finite values",
                       ErrorKind::invalid_option);
    }
    const Tri& t = element.triangles[fc.face];
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= nv) {
        throw InputError("element deformation: face " + std::to_string(fc.face) +
                         " has a vertex index outside [0, " + std::to_string(nv) + ")");
      }
    }
    rows.push_back(ConstraintRow{{t[0], t[1], t[2]}, {fc.barycentric.x, fc.barycentric.y, fc.barycentric.z}, 3,
                                 fc.target});
  }
  return solve_deformation(element, rows, options.mu);
}

}  // namespace meshquilt
