#include "surface/direction_field.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Sparse>
#include <glm/geometric.hpp>

#include "core/constants.h"
#include "numerics/sparse_solve.h"

namespace meshquilt {
namespace {


// An orthonormal tangent frame of a face: x along its first edge, y = normal x x.
struct FaceFrame {
  Vec3 x{1.0, 0.0, 0.0}, y{0.0, 1.0, 0.0};
};

FaceFrame face_frame(const BaseSurface& base, int32_t f) {
  const Tri& t = base.mesh.triangles[f];
  const Vec3 n = base.face_normals[f];
  const Vec3 e = base.mesh.positions[t[1]] - base.mesh.positions[t[0]];
  if (base.face_areas[f] <= 0.0 || !(glm::length(e) > 0.0)) return {};
  const Vec3 x = glm::normalize(e);
  return {x, glm::cross(n, x)};
}

double angle_in(const FaceFrame& frame, const Vec3& d) { return std::atan2(glm::dot(d, frame.y), glm::dot(d, frame.x)); }

// Wraps an angle into (-period / 2, period / 2].
double wrapped(double angle, double period) { return angle - period * std::round(angle / period); }

}  // namespace

Vec3 transport_across(const BaseSurface& base, int32_t f, int32_t g, int32_t a, int32_t b, const Vec3& d) {
  const Vec3 e = base.mesh.positions[b] - base.mesh.positions[a];
  const double len = glm::length(e);
  if (!(len > 0.0)) return d;
  const Vec3 x = e / len;
  const Vec3 yf = glm::cross(base.face_normals[f], x), yg = glm::cross(base.face_normals[g], x);
  return glm::dot(d, x) * x + glm::dot(d, yf) * yg;
}

double signed_angle(const Vec3& from, const Vec3& to, const Vec3& normal) {
  return std::atan2(glm::dot(glm::cross(from, to), normal), glm::dot(from, to));
}

FieldTargets field_targets(const BaseSurface& base, const GuidanceField& guidance) {
  const size_t faces = base.mesh.num_faces();
  FieldTargets out;
  out.target.resize(faces);
  for (size_t f = 0; f < faces; ++f) out.target[f] = guidance.at(base, {static_cast<int32_t>(f), glm::dvec2(1.0 / 3.0)});
  out.weight.assign(faces, guidance.held_vertices.empty() ? default_field_weight(base) : guided_field_weight(base));
  for (int32_t v : guidance.held_vertices)
    for (int32_t f : base.vertex_faces[v]) out.weight[f] = 10.0;
  return out;
}

double default_field_weight(const BaseSurface& base) {
  // Below the smallest eigenvalue of the connection Laplacian (about 1 / #F on a surface of mean
  // face area 1) by a hundredfold.
  return 1e-4 / static_cast<double>(std::max<size_t>(base.mesh.num_faces(), 1));
}

double guided_field_weight(const BaseSurface& base) {
  // Ten times that eigenvalue: the field keeps the target's directions, smoothed.
  return 10.0 / static_cast<double>(std::max<size_t>(base.mesh.num_faces(), 1));
}

DirectionField smoothest_direction_field(const BaseSurface& base, int symmetry, const std::vector<Vec3>& target,
                                         const std::vector<double>& weight) {
  const TriMesh& mesh = base.mesh;
  const auto faces = static_cast<int32_t>(mesh.num_faces());
  const double n = symmetry;
  std::vector<FaceFrame> frames(static_cast<size_t>(faces));
  for (int32_t f = 0; f < faces; ++f) frames[f] = face_frame(base, f);
  const double mean_area = faces > 0 ? base.area / faces : 1.0;
  // Unknowns: the real and imaginary parts of u_f at 2f, 2f + 1.
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * faces);
  const auto add = [&](int32_t row, int32_t column, double value) { triplets.emplace_back(row, column, value); };
  for (int32_t f = 0; f < faces; ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (g <= f || base.face_areas[f] <= 0.0 || base.face_areas[g] <= 0.0) continue;
      const Vec3 e = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
      // Residual u_g - r u_f with r = exp(i n (theta_g - theta_f)) = c + i s, real and imaginary
      // rows: (a_g - c a_f + s b_f, b_g - s a_f - c b_f).
      const double turn = n * (angle_in(frames[g], e) - angle_in(frames[f], e));
      const double c = std::cos(turn), s = std::sin(turn);
      const int32_t af = 2 * f, bf = 2 * f + 1, ag = 2 * g, bg = 2 * g + 1;
      const std::pair<int32_t, double> rows[2][3] = {{{ag, 1.0}, {af, -c}, {bf, s}}, {{bg, 1.0}, {af, -s}, {bf, -c}}};
      for (const auto& row : rows)
        for (const auto& [i, wi] : row)
          for (const auto& [j, wj] : row) add(i, j, wi * wj);
    }
  }
  for (int32_t f = 0; f < faces; ++f) {
    const double w = weight[f] * std::max(base.face_areas[f], 1e-12 * mean_area) / mean_area;
    add(2 * f, 2 * f, w);
    add(2 * f + 1, 2 * f + 1, w);
    const Vec3 q = target[f] - glm::dot(target[f], base.face_normals[f]) * base.face_normals[f];
    if (!(glm::length(q) > 0.0)) continue;
    const double angle = n * angle_in(frames[f], q);
    rhs(2 * f) += w * std::cos(angle);
    rhs(2 * f + 1) += w * std::sin(angle);
  }
  DirectionField field;
  field.symmetry = symmetry;
  field.directions.resize(static_cast<size_t>(faces));
  if (faces == 0) return field;
  Eigen::SparseMatrix<double> A(2 * faces, 2 * faces);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd u = solve_positive_definite(A, rhs, "direction field");
  for (int32_t f = 0; f < faces; ++f) {
    const double angle = std::atan2(u(2 * f + 1, 0), u(2 * f, 0)) / n;
    field.directions[f] = std::cos(angle) * frames[f].x + std::sin(angle) * frames[f].y;
  }
  return field;
}

std::vector<int> field_indices(const BaseSurface& base, const DirectionField& field) {
  const TriMesh& mesh = base.mesh;
  const double period = 2.0 * kPi / field.symmetry;
  std::vector<int> index(mesh.num_vertices(), 0);
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    const auto& around = base.vertex_faces[v];
    if (around.empty()) continue;
    // Counter-clockwise round v: from face f (v = t[j]) across its edge (t[j + 2], v).
    double turn = 0.0, angles = 0.0;
    int32_t f = around.front();
    size_t steps = 0;
    bool closed = false;
    while (steps++ <= around.size()) {
      const Tri& t = mesh.triangles[f];
      const int j = t[0] == static_cast<int32_t>(v) ? 0 : t[1] == static_cast<int32_t>(v) ? 1 : 2;
      const Vec3 p = mesh.positions[v];
      const Vec3 to_a = mesh.positions[t[(j + 1) % 3]] - p, to_b = mesh.positions[t[(j + 2) % 3]] - p;
      if (glm::length(to_a) > 0.0 && glm::length(to_b) > 0.0)
        angles += std::acos(std::clamp(glm::dot(glm::normalize(to_a), glm::normalize(to_b)), -1.0, 1.0));
      const int32_t g = base.face_across[f][(j + 2) % 3];
      if (g < 0) break;
      const Vec3 carried = transport_across(base, f, g, t[(j + 2) % 3], static_cast<int32_t>(v), field.directions[f]);
      turn += wrapped(signed_angle(carried, field.directions[g], base.face_normals[g]), period);
      f = g;
      if (f == around.front()) {
        closed = steps == around.size();
        break;
      }
    }
    if (!closed) continue;  // a boundary or non-manifold vertex
    const double defect = 2.0 * kPi - angles;
    index[v] = static_cast<int>(std::lround((turn + defect) / period));
  }
  return index;
}

}  // namespace meshquilt
