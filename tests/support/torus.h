#pragma once
// A torus for tests, built here independently of the code under test.

#include <cmath>

#include "mesh/tri_mesh.h"

namespace meshquilt::test {

// A torus of `segments` x `sides` quads about the z axis (major radius R, minor r), outward faces.
inline TriMesh torus(double R, double r, int segments = 24, int sides = 8) {
  TriMesh m;
  const double tau = 2.0 * 3.14159265358979323846;
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < sides; ++j) {
      const double u = tau * i / segments, v = tau * j / sides;
      m.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                               r * std::sin(v));
    }
  const auto at = [&](int i, int j) { return static_cast<int32_t>((i % segments) * sides + j % sides); };
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < sides; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// The torus(1, 0.3) with its x < 0 half pushed by +1.5 in x: that half's tube crosses the other
// half's through faces that share no vertex, while the mesh stays one closed 2-manifold.
inline TriMesh folded_torus() {
  TriMesh m = torus(1.0, 0.3);
  for (Vec3& p : m.positions)
    if (p.x < -1e-9) p.x += 1.5;
  return m;
}

}  // namespace meshquilt::test
