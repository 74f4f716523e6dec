// Local frames of output vertices against maps known in closed form: a translation (the
// identity), a similarity (its rotation and scale), and a wrap around a cylinder (the rotation
// about its axis by the arc angle).
#include "edit/swatch_animation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/error.h"
#include "support/torus.h"

namespace meshquilt {
namespace {

// The torus as its own output, every vertex its own origin, mapped through `map`.
template <typename Map>
TriMesh mapped_torus(const TriMesh& swatch, Map map) {
  TriMesh out = swatch;
  for (Vec3& p : out.positions) p = map(p);
  out.origins.resize(out.num_vertices());
  std::iota(out.origins.begin(), out.origins.end(), 0);
  return out;
}

double largest_entry(const glm::dmat3& m) {
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(m[c][r]));
  return largest;
}

TEST(SwatchAnimation, ATranslatedCopyMovesExactlyWithItsSwatch) {
  const TriMesh swatch = test::torus(1.0, 0.3, 24, 8);
  const TriMesh out = mapped_torus(swatch, [](const Vec3& p) { return p + Vec3(5.0, -2.0, 0.25); });
  const auto frames = vertex_frames(out, swatch.positions);
  for (const glm::dmat3& f : frames) EXPECT_LT(largest_entry(f - glm::dmat3(1.0)), 1e-9);
  // No displacement: the very same positions; a rigid one: the same offset everywhere.
  EXPECT_EQ(animated_positions(out, frames, swatch.positions, swatch.positions), out.positions);
  std::vector<Vec3> shifted = swatch.positions;
  for (Vec3& p : shifted) p += Vec3(0.1, 0.2, -0.3);
  const auto moved = animated_positions(out, frames, swatch.positions, shifted);
  for (size_t v = 0; v < moved.size(); ++v)
    EXPECT_LT(glm::length(moved[v] - out.positions[v] - Vec3(0.1, 0.2, -0.3)), 1e-9);
}

TEST(SwatchAnimation, ASimilarityGivesItsRotationAndScale) {
  const TriMesh swatch = test::torus(1.0, 0.3, 24, 8);
  const double a = 0.7, b = -0.4, s = 2.5;
  // A turn about z by a, then about x by b.
  const glm::dmat3 rz(std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0);
  const glm::dmat3 rx(1.0, 0.0, 0.0, 0.0, std::cos(b), std::sin(b), 0.0, -std::sin(b), std::cos(b));
  const glm::dmat3 expected = s * rx * rz;
  const TriMesh out = mapped_torus(swatch, [&](const Vec3& p) { return expected * p + Vec3(1.0, 2.0, 3.0); });
  for (const glm::dmat3& f : vertex_frames(out, swatch.positions))
    EXPECT_LT(largest_entry(f - expected), 1e-9);
}

TEST(SwatchAnimation, AWrapAroundACylinderTurnsByTheArcAngle) {
  // The torus lies in x-y; wrap x around a cylinder of radius 8 about the y axis (z the height).
  const TriMesh swatch = test::torus(1.0, 0.3, 96, 16);
  const double radius = 8.0;
  const TriMesh out = mapped_torus(swatch, [&](const Vec3& p) {
    const double r = radius + p.z, angle = p.x / radius;
    return Vec3(r * std::sin(angle), p.y, r * std::cos(angle));
  });
  const auto frames = vertex_frames(out, swatch.positions);
  double worst = 0.0;
  for (size_t v = 0; v < frames.size(); ++v) {
    const double angle = swatch.positions[v].x / radius;
    // The rotation about y taking x to the arc's tangent and z to the cylinder's normal.
    const glm::dmat3 turn(std::cos(angle), 0.0, -std::sin(angle), 0.0, 1.0, 0.0, std::sin(angle), 0.0,
                          std::cos(angle));
    const double scale = std::cbrt(glm::determinant(frames[v]));
    worst = std::max(worst, largest_entry(frames[v] / scale - turn));
    EXPECT_NEAR(scale, 1.0, 0.05);
  }
  // The fit is first order over a neighbourhood of 6 rings (about 0.5 units, 0.06 rad of arc).
  EXPECT_LT(worst, 0.04);
}

TEST(SwatchAnimation, AResultWithoutOriginsIsRefused) {
  const TriMesh swatch = test::torus(1.0, 0.3);
  EXPECT_THROW(vertex_frames(swatch, swatch.positions), InputError);
  TriMesh out = mapped_torus(swatch, [](const Vec3& p) { return p; });
  out.origins[3] = static_cast<int32_t>(swatch.num_vertices());
  EXPECT_THROW(vertex_frames(out, swatch.positions), InputError);
}

}  // namespace
}  // namespace meshquilt
