#include "numerics/symmetric_eigen.h"

#include <Eigen/Dense>

namespace meshquilt {

std::array<Vec3, 3> symmetric_eigenvectors(const Symmetric3& m) {
  Eigen::Matrix3d matrix;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) matrix(i, j) = m[i][j];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(matrix);
  std::array<Vec3, 3> vectors;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d v = solver.eigenvectors().col(k);
    vectors[k] = Vec3(v.x(), v.y(), v.z());
  }
  return vectors;
}

}  // namespace meshquilt
