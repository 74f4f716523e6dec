// passes_through against every candidate-other face pair tested exactly: the broad phase may
// never miss a pair, touching included.
#include <gtest/gtest.h>

#include <random>

#include "quilt/quilt_policies.h"
#include "spatial/triangle_intersection.h"
#include "swatch/chainmail.h"

namespace meshquilt {
namespace {

bool brute_force(const TriMesh& candidate, const std::vector<const TriMesh*>& others) {
  for (const Tri& a : candidate.triangles)
    for (const TriMesh* other : others)
      for (const Tri& b : other->triangles) {
        const auto& x = candidate.positions;
        const auto& y = other->positions;
        if (triangles_intersect(x[a[0]], x[a[1]], x[a[2]], y[b[0]], y[b[1]], y[b[2]])) return true;
      }
  return false;
}

TriMesh moved(const TriMesh& mesh, const Vec3& by) {
  TriMesh out = mesh;
  for (Vec3& p : out.positions) p += by;
  return out;
}

// One ring of the small chain mail, and copies of it scattered around: some pass through it,
// some miss it by a little.
TEST(PassesThrough, AgreesWithEveryPairTestedExactly) {
  ChainmailOptions options = ChainmailOptions::small();
  options.rows = 2;
  options.columns = 1;
  const TriMesh rings = make_chainmail(options);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> shift(-3.5, 3.5);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<TriMesh> placed;
    for (int k = 0; k < 3; ++k) placed.push_back(moved(rings, Vec3(shift(rng), shift(rng), 0.2 * shift(rng))));
    std::vector<const TriMesh*> others;
    for (const TriMesh& p : placed) others.push_back(&p);
    const bool expected = brute_force(rings, others);
    EXPECT_EQ(passes_through(rings, others), expected) << "trial " << trial;
    (expected ? hits : misses) += 1;
  }
  EXPECT_GT(hits, 5);
  EXPECT_GT(misses, 5);
}

TEST(PassesThrough, TouchingCountsAndNothingIsNothing) {
  TriMesh a;
  a.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  a.triangles = {{0, 1, 2}};
  TriMesh touching;  // stands on a's edge
  touching.positions = {{0.5, 0, 0}, {0.5, 0, 1}, {0.5, -1, 1}};
  touching.triangles = {{0, 1, 2}};
  const TriMesh apart = moved(touching, Vec3(0.0, -1e-9, 0.0));
  EXPECT_TRUE(passes_through(a, {&touching}));
  EXPECT_EQ(passes_through(a, {&apart}), brute_force(a, {&apart}));
  EXPECT_FALSE(passes_through(a, std::vector<const TriMesh*>{}));
  EXPECT_FALSE(passes_through(TriMesh{}, {&touching}));
}

// Runs of consecutive faces, each box holding its faces' corners; a ring's runs, kept by the
// caller, answer as the runs measured per call do.
TEST(PassesThrough, FaceRunsHoldTheirFacesAndKeptRunsAnswerTheSame) {
  ChainmailOptions options = ChainmailOptions::small();
  options.rows = 2;
  options.columns = 1;
  const TriMesh rings = make_chainmail(options);
  const std::vector<Box3> runs = face_run_boxes(rings);
  ASSERT_EQ(runs.size(), (rings.num_faces() + kFaceRun - 1) / kFaceRun);
  for (size_t f = 0; f < rings.num_faces(); ++f)
    for (int32_t v : rings.triangles[f]) {
      const Vec3& p = rings.positions[v];
      const Box3& run = runs[f / kFaceRun];
      EXPECT_TRUE(run.lo.x <= p.x && p.x <= run.hi.x && run.lo.y <= p.y && p.y <= run.hi.y && run.lo.z <= p.z &&
                  p.z <= run.hi.z)
          << "face " << f;
    }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> shift(-3.0, 3.0);
  int hits = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const TriMesh other = moved(rings, Vec3(shift(rng), shift(rng), 0.2 * shift(rng)));
    const std::vector<Box3> other_runs = face_run_boxes(other);
    const bool expected = brute_force(rings, {&other});
    EXPECT_EQ(passes_through(rings, std::vector<CollisionMesh>{{&other, &other_runs}}), expected) << "trial " << trial;
    hits += expected;
  }
  EXPECT_GT(hits, 3);
  EXPECT_LT(hits, 27);
}

}  // namespace
}  // namespace meshquilt
