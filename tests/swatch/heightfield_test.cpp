// The height-field generator: closed slabs or open sheets that follow the image, tiles with grout.
#include <gtest/gtest.h>

#include "swatch/heightfield.h"
#include "swatch_checks.h"

namespace meshquilt {
namespace {

using namespace swatch_checks;

// ---------------------------------------------------------------------------------------------
// Height field.

TEST(Heightfield, DefaultsAreAClosedSlab) {
  const HeightfieldOptions o;
  const TriMesh m = make_heightfield(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {1, true, 2}, "heightfield_default");
  check_round_trip(m, "heightfield_default");
}

TEST(Heightfield, SmallPresetClosedAndOpen) {
  HeightfieldOptions o = HeightfieldOptions::small();
  const TriMesh closed = make_heightfield(o);
  EXPECT_LE(closed.num_faces(), 2000u);
  check_swatch(closed, {1, true, 2}, "heightfield_small");
  check_round_trip(closed, "heightfield_small");
  o.open = true;
  const TriMesh open = make_heightfield(o);
  EXPECT_EQ(open.num_faces(), 2u * 15 * 15);
  check_swatch(open, {1, false, 0}, "heightfield_small_open");
  check_round_trip(open, "heightfield_small_open");
  // The open sheet's boundary is the rim of the pixel grid.
  EXPECT_EQ(element_topology(open)[0].boundary_edges, 4 * 15);
  EXPECT_EQ(element_topology(open)[0].euler, 1);
}

TEST(Heightfield, TilesAreSeparateSlabsWithGrout) {
  HeightfieldOptions o = HeightfieldOptions::small();  // 16 x 16 pixels
  o.tiles = 4;                                         // 4 pixels a tile: 3 x 3 quads, one spacing apart
  const TriMesh tiles = make_heightfield(o);
  check_swatch(tiles, {16, true, 2}, "heightfield_tiles");
  check_round_trip(tiles, "heightfield_tiles");
  EXPECT_EQ(tiles.num_faces(), 16u * (4 * 3 * 3 + 4 * (3 + 3)));
  // Each tile's top is the one-piece slab's top over the same pixels: every tile vertex is a
  // vertex of the one-piece slab, and no two tiles come closer than one pixel spacing.
  const TriMesh whole = make_heightfield(HeightfieldOptions::small());
  std::set<std::tuple<double, double, double>> slab;
  for (const Vec3& p : whole.positions) slab.insert({p.x, p.y, p.z});
  for (const Vec3& p : tiles.positions) EXPECT_TRUE(slab.count({p.x, p.y, p.z})) << p.x << " " << p.y << " " << p.z;
  const double spacing = o.size / 15.0;
  std::map<int32_t, std::pair<glm::dvec2, glm::dvec2>> box;
  for (size_t f = 0; f < tiles.num_faces(); ++f)
    for (int32_t v : tiles.triangles[f]) {
      auto [it, fresh] = box.try_emplace(tiles.elements[f], glm::dvec2(1e300), glm::dvec2(-1e300));
      it->second.first = glm::min(it->second.first, glm::dvec2(tiles.positions[v]));
      it->second.second = glm::max(it->second.second, glm::dvec2(tiles.positions[v]));
    }
  for (const auto& [e, b] : box) EXPECT_NEAR(b.second.x - b.first.x, 3 * spacing, 1e-9) << e;
  for (const auto& [a, ba] : box)
    for (const auto& [b, bb] : box) {
      if (a >= b) continue;
      const double gap = std::max({bb.first.x - ba.second.x, ba.first.x - bb.second.x, bb.first.y - ba.second.y,
                                   ba.first.y - bb.second.y});
      EXPECT_GE(gap, spacing - 1e-9) << a << " " << b;
    }
  o.tiles = 6;  // 2 pixels a tile
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
  o.tiles = 0;
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
}

TEST(Heightfield, HeightsFollowTheImageUpright) {
  HeightfieldOptions o;
  o.image.width = 3;
  o.image.height = 2;
  o.image.values = {0.0, 0.25, 0.5,   // top row: largest y
                    0.75, 1.0, 0.1};  // bottom row: y = 0
  o.size = 4.0;  // spacing 2
  o.height = 1.0;
  o.base = 0.2;
  const TriMesh m = make_heightfield(o);
  check_swatch(m, {1, true, 2}, "heightfield_tiny");
  auto z_at = [&](double x, double y) {
    double best = -INFINITY;
    for (const Vec3& p : m.positions)
      if (std::abs(p.x - x) < 1e-12 && std::abs(p.y - y) < 1e-12) best = std::max(best, p.z);
    return best;
  };
  EXPECT_DOUBLE_EQ(z_at(0, 2), 0.0);
  EXPECT_DOUBLE_EQ(z_at(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(z_at(4, 2), 0.5);
  EXPECT_DOUBLE_EQ(z_at(0, 0), 0.75);
  EXPECT_DOUBLE_EQ(z_at(2, 0), 1.0);
  EXPECT_DOUBLE_EQ(z_at(4, 0), 0.1);
  EXPECT_DOUBLE_EQ(bounds(m).lo.z, -0.2);
}

TEST(Heightfield, RejectsReliefThickerThanWide) {
  HeightfieldOptions o = HeightfieldOptions::small();
  o.height = 20.0;
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
  o = HeightfieldOptions::small();
  o.image.width = 1;
  o.image.height = 5;
  o.image.values.assign(5, 0.5);
  EXPECT_EQ(error_code([&] { make_heightfield(o); }), ErrorKind::invalid_option);
}

TEST(Heightfield, LargeImagesAreBoxFiltered) {
  GrayImage image;
  image.width = 8;
  image.height = 4;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c) image.values.push_back(c < 4 ? 0.0 : 1.0);
  const GrayImage small = downsample_image(image, 4);
  ASSERT_EQ(small.width, 4);
  ASSERT_EQ(small.height, 2);
  EXPECT_DOUBLE_EQ(small.at(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(small.at(1, 1), 0.0);
  EXPECT_DOUBLE_EQ(small.at(2, 0), 1.0);
  EXPECT_DOUBLE_EQ(small.at(3, 1), 1.0);
}


}  // namespace
}  // namespace meshquilt
