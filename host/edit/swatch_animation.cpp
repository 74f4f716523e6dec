#include "edit/swatch_animation.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace meshquilt {
namespace {

// Vertex adjacency by edges (each vertex's neighbours, sorted).
std::vector<std::vector<int32_t>> neighbours(const TriMesh& mesh) {
  std::vector<std::vector<int32_t>> adjacent(mesh.num_vertices());
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      adjacent[t[k]].push_back(t[(k + 1) % 3]);
      adjacent[t[k]].push_back(t[(k + 2) % 3]);
    }
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacent;
}

// The polar rotation times the volume scale of the least-squares map from `from` to `to`
// offsets; false when the offsets do not span three dimensions.
bool fit_frame(const std::vector<Vec3>& from, const std::vector<Vec3>& to, glm::dmat3& frame) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero(), b = Eigen::Matrix3d::Zero();
  for (size_t k = 0; k < from.size(); ++k) {
    const Eigen::Vector3d q(from[k].x, from[k].y, from[k].z), x(to[k].x, to[k].y, to[k].z);
    a += q * q.transpose();
    b += x * q.transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> conditioning(a);
  const Eigen::Vector3d spread = conditioning.singularValues();
  if (!(spread(2) > 1e-8 * spread(0))) return false;
  const Eigen::Matrix3d j = b * a.inverse();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(j, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0.0) u.col(2) *= -1.0;
  const Eigen::Vector3d sigma = svd.singularValues();
  const double scale = std::cbrt(sigma(0) * sigma(1) * sigma(2));
  const Eigen::Matrix3d r = scale * u * v.transpose();
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) frame[c][row] = r(row, c);  // glm is column-major
  return true;
}

}  // namespace

std::vector<glm::dmat3> vertex_frames(const TriMesh& output, const std::vector<Vec3>& swatch_rest,
                                      int rings) {
  if (output.origins.size() != output.num_vertices())
    throw InputError("the result names no swatch vertex per vertex (write it with synth {provenance})");
  for (int32_t o : output.origins)
    if (o >= static_cast<int32_t>(swatch_rest.size()))
      throw InputError("the result names swatch vertex " + std::to_string(o) + " but the swatch has " +
                       std::to_string(swatch_rest.size()));
  const auto adjacent = neighbours(output);
  std::vector<glm::dmat3> frames(output.num_vertices(), glm::dmat3(1.0));
  std::vector<int32_t> seen(output.num_vertices(), -1), front, next;
  std::vector<Vec3> from, to;
  for (size_t v = 0; v < output.num_vertices(); ++v) {
    if (output.origins[v] < 0) continue;
    // Widen the neighbourhood ring by ring until the swatch offsets span three dimensions.
    front.assign(1, static_cast<int32_t>(v));
    seen[v] = static_cast<int32_t>(v);
    from.clear();
    to.clear();
    const Vec3 q0 = swatch_rest[output.origins[v]], x0 = output.positions[v];
    for (int ring = 1; ring <= 4 * rings && !front.empty(); ++ring) {
      next.clear();
      for (int32_t a : front)
        for (int32_t b : adjacent[a])
          if (seen[b] != static_cast<int32_t>(v)) {
            seen[b] = static_cast<int32_t>(v);
            next.push_back(b);
            if (output.origins[b] >= 0) {
              from.push_back(swatch_rest[output.origins[b]] - q0);
              to.push_back(output.positions[b] - x0);
            }
          }
      front.swap(next);
      if (ring >= rings && fit_frame(from, to, frames[v])) break;
    }
  }
  return frames;
}

std::vector<Vec3> animated_positions(const TriMesh& output, const std::vector<glm::dmat3>& frames,
                                     const std::vector<Vec3>& swatch_rest,
                                     const std::vector<Vec3>& swatch_frame) {
  std::vector<Vec3> moved = output.positions;
  for (size_t v = 0; v < moved.size(); ++v) {
    const int32_t o = output.origins.empty() ? -1 : output.origins[v];
    if (o < 0) continue;
    const Vec3 d = swatch_frame[o] - swatch_rest[o];
    if (d != Vec3(0.0)) moved[v] += frames[v] * d;
  }
  return moved;
}

}  // namespace meshquilt
