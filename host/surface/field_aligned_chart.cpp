#include "surface/field_aligned_chart.h"

#include <glm/geometric.hpp>

#include "numerics/sparse_solve.h"

namespace meshquilt {

std::vector<glm::dvec2> field_aligned_flattening(const BaseSurface& base, const std::vector<int32_t>& faces,
                                                 const std::vector<int32_t>& corner_vertex,
                                                 const std::vector<int32_t>& vertex_base,
                                                 const std::vector<Vec3>& face_field) {
  const TriMesh& mesh = base.mesh;
  const auto n = static_cast<int32_t>(vertex_base.size());
  const int32_t pin = corner_vertex.empty() ? 0 : corner_vertex[0];
  // Unknowns: every vertex but the pinned one.
  std::vector<int32_t> column(static_cast<size_t>(n), -1);
  int32_t unknowns = 0;
  for (int32_t k = 0; k < n; ++k)
    if (k != pin) column[k] = unknowns++;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 2);
  double diagonal = 0.0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const Tri& t = mesh.triangles[faces[f]];
    const double area = base.face_areas[faces[f]];
    const Vec3 normal = base.face_normals[faces[f]];
    Vec3 d = face_field[faces[f]] - glm::dot(face_field[faces[f]], normal) * normal;
    if (area <= 0.0 || !(glm::length(d) > 0.0)) continue;
    d = glm::normalize(d);
    const Vec3 frame[2] = {d, glm::cross(normal, d)};
    // Gradient of corner k's hat function: normal x (opposite edge) / (2 area).
    Vec3 gradient[3];
    for (int k = 0; k < 3; ++k)
      gradient[k] = glm::cross(normal, mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[(k + 1) % 3]]) / (2.0 * area);
    for (int a = 0; a < 3; ++a) {
      const int32_t va = corner_vertex[3 * f + a];
      // Right-hand side: area * <grad phi_a, target gradient> for u (frame[0]) and v (frame[1]).
      if (column[va] >= 0)
        for (int c = 0; c < 2; ++c) rhs(column[va], c) += area * glm::dot(gradient[a], frame[c]);
      for (int b = 0; b < 3; ++b) {
        const int32_t vb = corner_vertex[3 * f + b];
        const double stiffness = area * glm::dot(gradient[a], gradient[b]);
        if (column[va] >= 0 && column[vb] >= 0) triplets.emplace_back(column[va], column[vb], stiffness);
        if (a == b) diagonal = std::max(diagonal, stiffness);
      }
    }
  }
  // A vertex only on zero-area faces has no equation: a faint pull to the origin keeps the
  // system definite without moving the others.
  for (int32_t k = 0; k < unknowns; ++k) triplets.emplace_back(k, k, 1e-12 * diagonal);
  std::vector<glm::dvec2> uv(static_cast<size_t>(n), glm::dvec2(0.0));
  if (unknowns == 0) return uv;
  Eigen::SparseMatrix<double> A(unknowns, unknowns);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd x = solve_positive_definite(A, rhs, "field-aligned chart");
  for (int32_t k = 0; k < n; ++k)
    if (column[k] >= 0) uv[k] = glm::dvec2(x(column[k], 0), x(column[k], 1));
  return uv;
}

}  // namespace meshquilt
