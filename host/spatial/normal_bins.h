#pragma once
//! Unit normals sorted into bins of nearby directions (cells of an octahedral map of the sphere),
//! each bin with a cone (axis, angular radius) that holds all its members. One cone test bounds
//! the normal term of Eq. 1, 1 + |n - m|, from below for every member m of a bin at once, so a
//! search over faces can pass over whole groups of faces that face away from a query.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

struct NormalBins {
  std::vector<uint32_t> bin_of;  //!< per input normal, its bin (bins without members are dropped)
  std::vector<Vec3> axis;        //!< per bin, the unit mean of its members
  std::vector<double> radius;    //!< per bin, the largest angle (radians) of a member to the axis, padded

  size_t size() const { return axis.size(); }
  //! For a unit n and every bin b, out[b] <= 1 + |n - m| for every unit m within the cone of b.
  //! Rounded down (by 1e-9 relative), so a comparison against costs computed in double holds.
  void factor_bounds(const Vec3& n, double* out) const;
};

//! Bins unit `normals` (#N) on a per_side x per_side octahedral grid (at most per_side^2 bins).
//! \pre per_side >= 1; normals are finite and unit length.
NormalBins bin_normals(const std::vector<Vec3>& normals, int per_side);

}  // namespace meshquilt
