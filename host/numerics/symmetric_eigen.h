#pragma once
//! Eigenvectors of small symmetric matrices (Eigen's self-adjoint solver): principal axes of a
//! covariance.

#include <array>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A symmetric 3 x 3 matrix, row by row.
using Symmetric3 = std::array<std::array<double, 3>, 3>;

//! Unit eigenvectors of `m`, in increasing order of their eigenvalues.
std::array<Vec3, 3> symmetric_eigenvectors(const Symmetric3& m);

}  // namespace meshquilt
