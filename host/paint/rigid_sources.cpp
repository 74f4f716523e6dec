#include "paint/rigid_sources.h"

#include <cmath>

#include <Eigen/Sparse>
#include <glm/geometric.hpp>

#include "numerics/sparse_solve.h"
#include "paint/field_frame.h"

namespace meshquilt {

std::vector<glm::dvec2> rigid_sources(const BaseSurface& surface, const std::vector<Vec3>& directions,
                                      double pixels_per_unit, const glm::dvec2& period,
                                      const std::vector<glm::dvec2>& sources, double cut, double hold) {
  const auto n = static_cast<Eigen::Index>(sources.size());
  std::vector<FieldFrame> frames;
  frames.reserve(sources.size());
  for (Eigen::Index v = 0; v < n; ++v) frames.push_back(field_frame(surface.vertex_normals[v], directions[v]));
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs(n, 2);
  for (Eigen::Index v = 0; v < n; ++v) {
    triplets.emplace_back(v, v, hold);
    rhs(v, 0) = hold * sources[v].x;
    rhs(v, 1) = hold * sources[v].y;
  }
  // Each edge once per face it bounds: an inner edge counts twice, a border edge once.
  for (const Tri& t : surface.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      const Vec3 q = surface.mesh.positions[b] - surface.mesh.positions[a];
      // The offset read in both ends' frames, which differ where the field turns.
      const glm::dvec2 o =
          0.5 * (frame_offset(frames[a], q, pixels_per_unit) + frame_offset(frames[b], q, pixels_per_unit));
      glm::dvec2 step = sources[b] - sources[a];
      step -= period * glm::round((step - o) / period);
      if (glm::length(step - o) > cut) continue;
      // The target is the offset shifted by the whole periods the positions wrapped by.
      const glm::dvec2 target = o + (sources[b] - sources[a] - step);
      triplets.emplace_back(a, a, 1.0);
      triplets.emplace_back(b, b, 1.0);
      triplets.emplace_back(a, b, -1.0);
      triplets.emplace_back(b, a, -1.0);
      rhs(a, 0) -= target.x;
      rhs(a, 1) -= target.y;
      rhs(b, 0) += target.x;
      rhs(b, 1) += target.y;
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd x = solve_positive_definite(A, rhs, "paint: rigid patches");
  std::vector<glm::dvec2> out(sources.size());
  for (Eigen::Index v = 0; v < n; ++v) {
    const glm::dvec2 p(x(v, 0), x(v, 1));
    out[v] = p - period * glm::floor(p / period);
  }
  return out;
}

}  // namespace meshquilt
