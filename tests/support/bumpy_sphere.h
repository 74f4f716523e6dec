#pragma once
// A closed, bumpy UV sphere for tests: poles plus rings x segments, perturbed radially so nothing
// is symmetric; outward normals, or inward when `flip`.

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>

#include "mesh/tri_mesh.h"

namespace meshquilt::test {

inline TriMesh bumpy_sphere(int rings, int segments, double radius, Vec3 centre, uint32_t seed,
                            double bumps = 0.08, bool flip = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-bumps, bumps);
  TriMesh m;
  m.positions.push_back(centre + Vec3(0, 0, radius));
  for (int r = 1; r <= rings; ++r) {
    const double theta = M_PI * r / (rings + 1);
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * M_PI * (s + 0.3 * r) / segments;
      const double rr = radius * (1 + jitter(rng));
      m.positions.push_back(centre + rr * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                               std::cos(theta)));
    }
  }
  m.positions.push_back(centre + Vec3(0, 0, -radius));
  const int south = int(m.positions.size()) - 1;
  auto at = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s), at(1, s + 1)});
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  for (int s = 0; s < segments; ++s) m.triangles.push_back({south, at(rings, s + 1), at(rings, s)});
  if (flip)
    for (Tri& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

}  // namespace meshquilt::test
