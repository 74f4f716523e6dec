#include "paint/sweep_order.h"

#include <algorithm>
#include <numeric>

#include <Eigen/Sparse>
#include <glm/geometric.hpp>

#include "numerics/sparse_solve.h"

namespace meshquilt {

std::vector<double> sweep_function(const BaseSurface& base, const std::vector<Vec3>& directions) {
  const TriMesh& mesh = base.mesh;
  const auto n = static_cast<Eigen::Index>(mesh.num_vertices());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 1);
  double largest = 0.0;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const double area = base.face_areas[f];
    if (!(area > 0.0)) continue;
    const Tri& t = mesh.triangles[f];
    const Vec3& normal = base.face_normals[f];
    // grad phi_i = normal x (edge opposite i, counter-clockwise) / (2 area).
    Vec3 gradient[3];
    for (int i = 0; i < 3; ++i) {
      const Vec3 edge = mesh.positions[t[(i + 2) % 3]] - mesh.positions[t[(i + 1) % 3]];
      gradient[i] = glm::cross(normal, edge) / (2.0 * area);
    }
    Vec3 d = directions[t[0]] + directions[t[1]] + directions[t[2]];
    d -= glm::dot(d, normal) * normal;
    if (glm::length(d) > 0.0) d = glm::normalize(d);
    for (int i = 0; i < 3; ++i) {
      rhs(t[i], 0) += area * glm::dot(gradient[i], d);
      for (int j = 0; j < 3; ++j) {
        const double value = area * glm::dot(gradient[i], gradient[j]);
        triplets.emplace_back(t[i], t[j], value);
        if (i == j) largest = std::max(largest, value);
      }
    }
  }
  // The energy does not see a constant: a pull to 0 far below every other term fixes it.
  for (Eigen::Index v = 0; v < n; ++v) triplets.emplace_back(v, v, 1e-9 * (largest > 0.0 ? largest : 1.0));
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd s = solve_positive_definite(A, rhs, "sweep function");
  return std::vector<double>(s.data(), s.data() + n);
}

std::vector<int32_t> sweep_order(const std::vector<double>& sweep) {
  std::vector<int32_t> order(sweep.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return sweep[a] < sweep[b]; });
  return order;
}

}  // namespace meshquilt
