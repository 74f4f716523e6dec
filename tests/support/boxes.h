#pragma once
// Axis-aligned boxes for tests, built here independently of the code under test.

#include "mesh/tri_mesh.h"

namespace meshquilt::test {

// An axis-aligned box [lo, hi] with outward faces; every square face is split along the diagonal
// through its corner of smallest coordinates, so boxes side by side share triangles exactly.
// `flip_x_diagonal` splits the two faces across x along the other diagonal.
inline TriMesh box(const Vec3& lo, const Vec3& hi, bool flip_x_diagonal = false) {
  TriMesh m;
  for (int k = 0; k < 8; ++k)
    m.positions.emplace_back(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
  // Quads as corners (a, b, c, d) counter-clockwise seen from outside, a the smallest corner.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (int q = 0; q < 6; ++q) {
    const int* c = quads[q];
    if (flip_x_diagonal && q < 2) {
      m.triangles.push_back({c[1], c[2], c[3]});
      m.triangles.push_back({c[1], c[3], c[0]});
    } else {
      m.triangles.push_back({c[0], c[1], c[2]});
      m.triangles.push_back({c[0], c[2], c[3]});
    }
  }
  return m;
}

// The box without its top (+z) face: an open element.
inline TriMesh open_box(const Vec3& lo, const Vec3& hi) {
  TriMesh m = box(lo, hi);
  m.triangles.resize(m.triangles.size() - 2);  // the +z quad comes last
  return m;
}

}  // namespace meshquilt::test
