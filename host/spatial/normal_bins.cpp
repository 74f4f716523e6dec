#include "spatial/normal_bins.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/constants.h"

namespace meshquilt {
namespace {

// The angle between two unit vectors, accurate at 0 and pi (acos of a dot is not).
double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// The octahedral map: the sphere onto [-1, 1]^2, with equal-area-ish cells.
int octahedral_cell(const Vec3& n, int per_side) {
  const double l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  double u = l1 > 0.0 ? n.x / l1 : 0.0, v = l1 > 0.0 ? n.y / l1 : 0.0;
  if (n.z < 0.0) {  // the lower half folds over the diagonals
    const double fu = (1.0 - std::abs(v)) * (u >= 0.0 ? 1.0 : -1.0);
    const double fv = (1.0 - std::abs(u)) * (v >= 0.0 ? 1.0 : -1.0);
    u = fu;
    v = fv;
  }
  const auto index = [per_side](double x) {
    return std::clamp(static_cast<int>(std::floor((x + 1.0) * 0.5 * per_side)), 0, per_side - 1);
  };
  return index(v) * per_side + index(u);
}

}  // namespace

NormalBins bin_normals(const std::vector<Vec3>& normals, int per_side) {
  NormalBins bins;
  std::vector<int> cell_bin(static_cast<size_t>(per_side) * per_side, -1);
  std::vector<Vec3> sums;
  bins.bin_of.reserve(normals.size());
  for (const Vec3& n : normals) {
    int& bin = cell_bin[octahedral_cell(n, per_side)];
    if (bin < 0) {
      bin = static_cast<int>(sums.size());
      sums.emplace_back(0.0);
    }
    sums[bin] += n;
    bins.bin_of.push_back(static_cast<uint32_t>(bin));
  }
  for (const Vec3& sum : sums) {
    const double length = glm::length(sum);
    bins.axis.push_back(length > 0.0 ? sum / length : Vec3(0.0, 0.0, 1.0));
  }
  bins.radius.assign(bins.axis.size(), 0.0);
  for (size_t i = 0; i < normals.size(); ++i) {
    const uint32_t b = bins.bin_of[i];
    bins.radius[b] = std::max(bins.radius[b], angle_between(normals[i], bins.axis[b]));
  }
  for (double& r : bins.radius) r = r * (1.0 + 1e-9) + 1e-9;  // atan2's rounding
  return bins;
}

void NormalBins::factor_bounds(const Vec3& n, double* out) const {
  // Members lie within radius of the axis, so their angle to n is at least angle(n, axis) -
  // radius (the triangle inequality on the sphere), and |n - m| = 2 sin(angle / 2) grows with it.
  for (size_t b = 0; b < axis.size(); ++b) {
    const double gap = std::clamp(angle_between(n, axis[b]) - radius[b], 0.0, kPi);
    out[b] = (1.0 + 2.0 * std::sin(0.5 * gap)) * (1.0 - 1e-9);
  }
}

}  // namespace meshquilt
