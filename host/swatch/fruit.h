#pragma once
//! Fruit swatches (the paper's "Plane + Apple"): smooth, slightly irregular apple-like blobs of
//! varied size and shape, lying in one layer without touching.

#include <cstdint>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Count, size and tessellation of a fruit swatch.
//! Each fruit is a subdivided icosahedron whose vertex directions d are pushed to radius
//! radius * s * rho(d), with s a random scale and rho a smooth star-shaped profile: a lopsided,
//! slightly tapered sphere with a stem dimple at the top and a calyx dimple at the bottom, its
//! coefficients drawn per fruit; then flattened in z by a random factor.
struct FruitOptions {
  int columns = 4;               //!< fruit per row (x)
  int rows = 4;                  //!< rows (y)
  double radius = 1.0;           //!< mean radius
  double size_variation = 0.15;  //!< scales drawn uniformly from [1 - v, 1 + v]; in [0, 0.5]
  double gap = 0.15;             //!< smallest horizontal distance between two fruit, > 0
  int subdivisions = 3;          //!< icosahedron subdivisions: 20 * 4^n faces per fruit, 1..6
  uint64_t seed = 1;             //!< seed of every random choice

  //! A small swatch for tests: 2 x 2 fruit, 2 subdivisions (1,280 faces).
  static FruitOptions small();
};

//! Builds the swatch: columns*rows closed genus-0 2-manifolds with outward orientation, one
//! element each (row-major), resting on z = 0 (each fruit's lowest point at z = 0), no two
//! closer than `gap` in x-y. The same options and seed give the same mesh, bit for bit.
//! \throw InputError(invalid_option) for counts < 1, subdivisions outside 1..6, non-positive
//!        radius or gap, or size_variation outside [0, 0.5].
TriMesh make_fruit(const FruitOptions& options);

}  // namespace meshquilt
