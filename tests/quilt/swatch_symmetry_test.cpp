// Rotational symmetry of swatches, on boxes built here (tiles, warps and wefts, tilted plates) and
// on the built-in chain mail and weave: the turns the shared surface layout may use at its seams.
#include <gtest/gtest.h>

#include <cmath>

#include "quilt/swatch_symmetry.h"
#include "swatch/chainmail.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

// Adds a box (half sizes h) turned by `tilt` about the y axis, centred at c, as one element.
void add_box(TriMesh& m, const Vec3& c, const Vec3& h, double tilt, int32_t source) {
  const auto first = static_cast<int32_t>(m.positions.size());
  const int32_t element = m.elements.empty() ? 0 : m.elements.back() + 1;
  for (int k = 0; k < 8; ++k) {
    const Vec3 p((k & 1 ? 1 : -1) * h.x, (k & 2 ? 1 : -1) * h.y, (k & 4 ? 1 : -1) * h.z);
    m.positions.push_back(c + Vec3(std::cos(tilt) * p.x + std::sin(tilt) * p.z, p.y, -std::sin(tilt) * p.x + std::cos(tilt) * p.z));
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({first + q[0], first + q[1], first + q[2]});
    m.triangles.push_back({first + q[0], first + q[2], first + q[3]});
    for (int k = 0; k < 2; ++k) {
      m.elements.push_back(element);
      m.sources.push_back(source);
    }
  }
}

int symmetry_of(const TriMesh& m) { return rotational_symmetry(prepare_swatch(m)); }
bool quarter_turn(const TriMesh& m) { return symmetric_under(prepare_swatch(m), 0.5 * 3.14159265358979323846); }

TEST(SwatchSymmetry, SquareTilesTakeAQuarterTurnButAreReportedTwoFold) {
  TriMesh m;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) add_box(m, Vec3(3.0 * i, 3.0 * j, 0.5), Vec3(1.0, 1.0, 0.3), 0.0, 0);
  EXPECT_TRUE(quarter_turn(m));
  EXPECT_EQ(symmetry_of(m), 2);
}

TEST(SwatchSymmetry, AQuarterTurnThatSwapsSourcesIsNoSymmetry) {
  TriMesh warps_and_wefts, one_source;
  for (int k = 0; k < 3; ++k) {
    add_box(warps_and_wefts, Vec3(3.0 * k, 4.0, 0.5), Vec3(0.4, 5.0, 0.3), 0.0, 0);
    add_box(warps_and_wefts, Vec3(4.0, 3.0 * k, 0.5), Vec3(5.0, 0.4, 0.3), 0.0, 1);
    add_box(one_source, Vec3(3.0 * k, 4.0, 0.5), Vec3(0.4, 5.0, 0.3), 0.0, 0);
    add_box(one_source, Vec3(4.0, 3.0 * k, 0.5), Vec3(5.0, 0.4, 0.3), 0.0, 0);
  }
  EXPECT_FALSE(quarter_turn(warps_and_wefts));
  EXPECT_TRUE(quarter_turn(one_source));
  EXPECT_EQ(symmetry_of(warps_and_wefts), 2);
}

TEST(SwatchSymmetry, PlatesTiltedOneWayHaveNoTurnBothWaysAHalfTurn) {
  TriMesh one_way, both_ways;
  for (int k = 0; k < 4; ++k) {
    add_box(one_way, Vec3(3.0 * k, 0.0, 1.0), Vec3(1.0, 0.6, 0.1), 0.4, 0);
    add_box(both_ways, Vec3(3.0 * k, 0.0, 1.0), Vec3(1.0, 0.6, 0.1), k % 2 ? 0.4 : -0.4, 0);
  }
  EXPECT_EQ(symmetry_of(one_way), 1);
  EXPECT_EQ(symmetry_of(both_ways), 2);
}

TEST(SwatchSymmetry, TheBuiltInChainMailAndWeaveAreTwoFold) {
  EXPECT_EQ(symmetry_of(make_chainmail(ChainmailOptions{})), 2);
  EXPECT_EQ(symmetry_of(make_weave(WeaveOptions{})), 2);
}

}  // namespace
}  // namespace meshquilt
