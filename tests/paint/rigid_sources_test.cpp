// rigid_sources against a closed form: on a plane with a constant field the rigid positions of a
// patch are the plane's coordinates in the field's frame plus one shift, so jittered copies of
// two such patches must come back rigid, each in its place, with the seam between them kept.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "paint/rigid_sources.h"
#include "support/surface_fixtures.h"
#include "surface/surface_types.h"

namespace meshquilt {
namespace {

constexpr double kPixelsPerUnit = 4.0;
const glm::dvec2 kPeriod(64.0, 48.0);

glm::dvec2 wrapped(const glm::dvec2& p) { return p - kPeriod * glm::floor(p / kPeriod); }

// The difference a - b taken the short way round the sample.
glm::dvec2 gap(const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 d = a - b;
  return d - kPeriod * glm::round(d / kPeriod);
}

struct TwoPatches {
  TriMesh plane = test::flat_grid(24, 20, 0.5, 0.3, 3);
  Vec3 x = glm::normalize(Vec3(2.0, 1.0, 0.0));
  Vec3 y;
  std::vector<glm::dvec2> exact;  // the rigid positions, wrapped
  std::vector<int> patch;         // 0 left of x = 6, 1 right of it

  TwoPatches() {
    const BaseSurface surface(plane);
    y = glm::normalize(glm::cross(surface.vertex_normals[0], x));
    for (const Vec3& p : plane.positions) {
      patch.push_back(p.x < 6.0 ? 0 : 1);
      // The right patch sits 20.3 pixels across from the left one; both cross the sample's
      // borders, which must not read as seams.
      const glm::dvec2 shift = patch.back() == 0 ? glm::dvec2(50.0, 30.0) : glm::dvec2(50.0, 50.3);
      exact.push_back(wrapped(shift + kPixelsPerUnit * glm::dvec2(glm::dot(p, x), glm::dot(p, y))));
    }
  }
};

TEST(RigidSources, MakesJitteredPatchesRigidAndKeepsTheSeam) {
  const TwoPatches fixture;
  const BaseSurface surface(fixture.plane);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  std::vector<glm::dvec2> jittered;
  for (const glm::dvec2& p : fixture.exact) jittered.push_back(wrapped(p + glm::dvec2(jitter(rng), jitter(rng))));
  const std::vector<Vec3> directions(fixture.plane.num_vertices(), fixture.x);
  const std::vector<glm::dvec2> rigid =
      rigid_sources(surface, directions, kPixelsPerUnit, kPeriod, jittered, 0.5);
  ASSERT_EQ(rigid.size(), jittered.size());
  double worst_before = 0.0, worst_after = 0.0;
  int seams = 0;
  for (const Tri& t : fixture.plane.triangles)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      const Vec3 q = fixture.plane.positions[b] - fixture.plane.positions[a];
      const glm::dvec2 truth = kPixelsPerUnit * glm::dvec2(glm::dot(q, fixture.x), glm::dot(q, fixture.y));
      if (fixture.patch[a] != fixture.patch[b]) {
        // Across the seam the positions still disagree by the 20.3 pixels between the patches.
        EXPECT_NEAR(glm::length(gap(rigid[b], rigid[a]) - truth), 20.3, 0.5);
        ++seams;
        continue;
      }
      worst_before = std::max(worst_before, glm::length(gap(jittered[b], jittered[a]) - truth));
      worst_after = std::max(worst_after, glm::length(gap(rigid[b], rigid[a]) - truth));
    }
  EXPECT_GT(seams, 20);
  EXPECT_GT(worst_before, 0.2);
  EXPECT_LT(worst_after, 0.02);
  for (size_t v = 0; v < rigid.size(); ++v) {
    // Inside the sample, and held near where it was: each patch moves by its jitter's mean only.
    EXPECT_GE(rigid[v].x, 0.0);
    EXPECT_LT(rigid[v].x, kPeriod.x);
    EXPECT_GE(rigid[v].y, 0.0);
    EXPECT_LT(rigid[v].y, kPeriod.y);
    EXPECT_LT(glm::length(gap(rigid[v], fixture.exact[v])), 0.1);
  }
}

TEST(RigidSources, LeavesRigidPatchesWhereTheyAre) {
  const TwoPatches fixture;
  const BaseSurface surface(fixture.plane);
  const std::vector<Vec3> directions(fixture.plane.num_vertices(), fixture.x);
  const std::vector<glm::dvec2> rigid =
      rigid_sources(surface, directions, kPixelsPerUnit, kPeriod, fixture.exact, 0.5);
  for (size_t v = 0; v < rigid.size(); ++v) EXPECT_LT(glm::length(gap(rigid[v], fixture.exact[v])), 1e-6);
}

}  // namespace
}  // namespace meshquilt
