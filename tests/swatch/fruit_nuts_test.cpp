// The fruit and nut generators: closed, disjoint elements of varied shapes, reproducible by seed.
#include <gtest/gtest.h>

#include "swatch/fruit.h"
#include "swatch/nuts.h"
#include "swatch_checks.h"

namespace meshquilt {
namespace {

using namespace swatch_checks;

// ---------------------------------------------------------------------------------------------
// Fruit and nuts.

TEST(Fruit, DefaultsAreClosedDisjointBlobs) {
  const FruitOptions o;
  const TriMesh m = make_fruit(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 21000u);
  check_swatch(m, {o.rows * o.columns, true, 2}, "fruit_default");
  check_round_trip(m, "fruit_default");
  EXPECT_NEAR(bounds(m).lo.z, 0.0, 1e-12);
}

TEST(Fruit, SmallPresetAndShapesVary) {
  const FruitOptions o = FruitOptions::small();
  const TriMesh m = make_fruit(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {4, true, 2}, "fruit_small");
  check_round_trip(m, "fruit_small");
  // Sizes vary: the elements' heights are not all equal.
  std::map<int32_t, Box> boxes;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int32_t v : m.triangles[f]) boxes[m.elements[f]].add(m.positions[v]);
  EXPECT_GT(std::abs(boxes[0].extent().z - boxes[1].extent().z), 1e-3);
}

TEST(Fruit, HasAStemPit) {
  // The highest points form a rim around the stem pit: near the rim's centre (the fruit's axis)
  // the surface stays well below the rim.
  FruitOptions o = FruitOptions::small();
  o.columns = o.rows = 1;
  o.subdivisions = 4;
  for (uint64_t seed : {1, 2, 3}) {
    o.seed = seed;
    const TriMesh m = make_fruit(o);
    std::vector<Vec3> by_height(m.positions);
    std::sort(by_height.begin(), by_height.end(), [](const Vec3& a, const Vec3& b) { return a.z > b.z; });
    const size_t rim = by_height.size() / 10;
    Vec3 axis(0.0);
    for (size_t k = 0; k < rim; ++k) axis += by_height[k] / static_cast<double>(rim);
    double top_at_axis = -INFINITY;
    for (const Vec3& p : m.positions)
      if (std::hypot(p.x - axis.x, p.y - axis.y) < 0.1 * o.radius) top_at_axis = std::max(top_at_axis, p.z);
    EXPECT_LT(top_at_axis, by_height.front().z - 0.05 * o.radius) << "seed " << seed;
  }
}

TEST(Nuts, DefaultsAreClosedGenusOneDisjoint) {
  const NutOptions o;
  const TriMesh m = make_nuts(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {o.rows * o.columns, true, 0}, "nuts_default");
  check_round_trip(m, "nuts_default");
}

TEST(Nuts, SmallPresetHasHoleAndVariedRotation) {
  const NutOptions o = NutOptions::small();
  const TriMesh m = make_nuts(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {4, true, 0}, "nuts_small");
  check_round_trip(m, "nuts_small");
  // Per nut: no vertex closer to the axis than the hole; the direction of the farthest vertex
  // (a hexagon corner) differs between nuts modulo 60 degrees.
  std::map<int32_t, Box> boxes;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int32_t v : m.triangles[f]) boxes[m.elements[f]].add(m.positions[v]);
  std::vector<double> corner_angles;
  for (const auto& [e, box] : boxes) {
    const Vec3 c = 0.5 * (box.lo + box.hi);
    double nearest = INFINITY, farthest = 0.0, angle = 0.0;
    for (size_t f = 0; f < m.triangles.size(); ++f) {
      if (m.elements[f] != e) continue;
      for (int32_t v : m.triangles[f]) {
        const double r = std::hypot(m.positions[v].x - c.x, m.positions[v].y - c.y);
        nearest = std::min(nearest, r);
        if (r > farthest) farthest = r, angle = std::atan2(m.positions[v].y - c.y, m.positions[v].x - c.x);
      }
    }
    EXPECT_GT(nearest, 0.4 * o.hole_radius);
    corner_angles.push_back(std::fmod(angle + 6.0 * M_PI, M_PI / 3.0));
  }
  std::sort(corner_angles.begin(), corner_angles.end());
  EXPECT_GT(corner_angles.back() - corner_angles.front(), 0.05);
}

TEST(RandomKinds, SameSeedSameBytesOtherSeedOtherBytes) {
  const fs::path dir = scratch("determinism");
  auto bytes_of = [&](const TriMesh& m, const std::string& name) {
    write_mesh(m, dir / name);
    return file_bytes(dir / name);
  };
  FruitOptions f = FruitOptions::small();
  const std::string f1 = bytes_of(make_fruit(f), "f1.ply"), f2 = bytes_of(make_fruit(f), "f2.ply");
  f.seed = 2;
  const std::string f3 = bytes_of(make_fruit(f), "f3.ply");
  EXPECT_EQ(f1, f2);
  EXPECT_NE(f1, f3);
  NutOptions n = NutOptions::small();
  const std::string n1 = bytes_of(make_nuts(n), "n1.ply"), n2 = bytes_of(make_nuts(n), "n2.ply");
  n.seed = 2;
  const std::string n3 = bytes_of(make_nuts(n), "n3.ply");
  EXPECT_EQ(n1, n2);
  EXPECT_NE(n1, n3);
  fs::remove_all(dir);
}


}  // namespace
}  // namespace meshquilt
