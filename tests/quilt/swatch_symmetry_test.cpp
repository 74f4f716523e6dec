// Rotational symmetry and periods of swatches, on boxes built here (tiles, warps and wefts, tilted
// plates, scattered ones) and on the built-in chain mail and weave: the turns and translations the
// shared surface layout may use at its seams.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "quilt/swatch_lattice.h"
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

// Plates in rows 2.5 apart, every other row shifted by half the 3.0 spacing and tilted the other
// way: a shift to the next row changes the tilt, so the periods are (3, 0) and (0, 5); a half
// turn about z swaps the tilts, about a point between a row and the next.
struct TiltedRows {
  TriMesh mesh;
  std::vector<glm::dvec2> centres;
  std::vector<int> tilt;  // +1 or -1 per plate
};

TiltedRows tilted_rows() {
  TiltedRows rows;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) {
      const glm::dvec2 c(3.0 * i + 1.5 * (j % 2), 2.5 * j);
      const int tilt = j % 2 ? 1 : -1;
      add_box(rows.mesh, Vec3(c.x, c.y, 1.0), Vec3(1.0, 0.6, 0.1), 0.4 * tilt, 0);
      rows.centres.push_back(c);
      rows.tilt.push_back(tilt);
    }
  return rows;
}

bool on_lattice(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const double det = a.x * b.y - a.y * b.x;
  const double k0 = (p.x * b.y - p.y * b.x) / det, k1 = (a.x * p.y - a.y * p.x) / det;
  return std::abs(k0 - std::round(k0)) < 1e-6 && std::abs(k1 - std::round(k1)) < 1e-6;
}

TEST(SwatchLattice, OffsetRowsOfTiltedPlatesRepeatEveryOtherRow) {
  const TiltedRows rows = tilted_rows();
  const QuiltSwatch swatch = prepare_swatch(rows.mesh);
  const std::optional<SwatchLattice> lattice = swatch_lattice(swatch, 1);
  ASSERT_TRUE(lattice.has_value());
  // The same lattice as (3, 0), (0, 5): each basis on the other's, of the same area.
  const auto& [a, b] = lattice->basis;
  EXPECT_TRUE(on_lattice(a, {3.0, 0.0}, {0.0, 5.0})) << a.x << " " << a.y;
  EXPECT_TRUE(on_lattice(b, {3.0, 0.0}, {0.0, 5.0})) << b.x << " " << b.y;
  EXPECT_NEAR(std::abs(a.x * b.y - a.y * b.x), 15.0, 1e-6);
}

TEST(SwatchLattice, AHalfTurnCentreMapsEveryPlateOntoOneTiltedTheOtherWay) {
  const TiltedRows rows = tilted_rows();
  const QuiltSwatch swatch = prepare_swatch(rows.mesh);
  const std::optional<SwatchLattice> lattice = swatch_lattice(swatch, 2);
  ASSERT_TRUE(lattice.has_value());
  // prepare_swatch moves the swatch to its frame: compare in that frame, through the plates'
  // own order (elements follow the input's).
  const glm::dvec2 shift = glm::dvec2(swatch.elements[0].positions[0]) - glm::dvec2(rows.mesh.positions[0]);
  const glm::dvec2 centre = lattice->centre - shift;
  int mapped = 0;
  for (size_t i = 0; i < rows.centres.size(); ++i) {
    const glm::dvec2 image = 2.0 * centre - rows.centres[i];
    for (size_t j = 0; j < rows.centres.size(); ++j)
      if (glm::distance(image, rows.centres[j]) < 1e-6) {
        EXPECT_EQ(rows.tilt[j], -rows.tilt[i]) << i << " -> " << j;
        ++mapped;
      }
  }
  // Every plate whose image lies within the rows: at least the middle ones.
  EXPECT_GE(mapped, 10);
}

TEST(SwatchLattice, ScatteredPlatesHaveNone) {
  TriMesh m;
  uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  for (int k = 0; k < 20; ++k) add_box(m, Vec3(20.0 * next(), 20.0 * next(), 1.0), Vec3(0.5, 0.5, 0.1), 0.0, 0);
  EXPECT_FALSE(swatch_lattice(prepare_swatch(m), 1).has_value());
}

TEST(SwatchLattice, TheBuiltInChainMailRepeatsOnItsRings) {
  const QuiltSwatch swatch = prepare_swatch(make_chainmail(ChainmailOptions{}));
  const std::optional<SwatchLattice> lattice = swatch_lattice(swatch, 2);
  ASSERT_TRUE(lattice.has_value());
  // Each period carries most ring centroids onto ring centroids, counted here directly.
  std::vector<glm::dvec2> centres;
  for (const TriMesh& ring : swatch.elements) {
    glm::dvec2 c(0.0);
    for (const Vec3& p : ring.positions) c += glm::dvec2(p);
    centres.push_back(c / static_cast<double>(ring.positions.size()));
  }
  for (const glm::dvec2& period : lattice->basis) {
    int hits = 0;
    for (const glm::dvec2& c : centres)
      for (const glm::dvec2& d : centres)
        if (glm::distance(c + period, d) < 1e-3 * glm::length(period)) ++hits;
    EXPECT_GE(hits, static_cast<int>(centres.size()) / 2) << period.x << " " << period.y;
  }
}

// A yarn moved by a period lies along another yarn: the periods show in the surface, checked here
// vertex by vertex against the swatch's own vertices (its mesh repeats exactly).
TEST(SwatchLattice, ThePlainWeaveRepeatsAlongAndAcrossItsYarns) {
  const QuiltSwatch swatch = prepare_swatch(make_weave(WeaveOptions{}));
  const std::optional<SwatchLattice> lattice = swatch_lattice(swatch, 2);
  ASSERT_TRUE(lattice.has_value());
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : swatch.mesh.positions) {
    lo = glm::min(lo, glm::dvec2(p));
    hi = glm::max(hi, glm::dvec2(p));
  }
  const double margin = 3.0 * swatch.mean_edge, tolerance = 1e-6 * glm::length(hi - lo);
  const auto maps_onto_itself = [&](const auto& map) {
    int landed = 0, matched = 0;
    for (size_t i = 0; i < swatch.mesh.positions.size(); i += 7) {
      const Vec3& p = swatch.mesh.positions[i];
      const glm::dvec2 q = map(glm::dvec2(p));
      if (q.x < lo.x + margin || q.y < lo.y + margin || q.x > hi.x - margin || q.y > hi.y - margin) continue;
      ++landed;
      for (const Vec3& r : swatch.mesh.positions)
        if (glm::distance(Vec3(q, p.z), r) <= tolerance) {
          ++matched;
          break;
        }
    }
    return landed > 100 && matched >= 0.9 * landed;
  };
  for (const glm::dvec2& period : lattice->basis)
    EXPECT_TRUE(maps_onto_itself([&](const glm::dvec2& p) { return p + period; })) << period.x << " " << period.y;
  const glm::dvec2 c = lattice->centre;
  EXPECT_TRUE(maps_onto_itself([&](const glm::dvec2& p) { return 2.0 * c - p; }));
  // Not every step between two yarns is one: half a period puts a warp where its neighbour is,
  // over where the neighbour goes under.
  EXPECT_FALSE(maps_onto_itself([&](const glm::dvec2& p) { return p + 0.5 * lattice->basis[0]; }));
}

// The plain weave as another tool might write it: turned 230 degrees about z, every vertex
// jittered by up to 0.3% of the pitch. Centroids of jittered yarns put a period off by more than
// the surface allows, and the turned swatch's box has bare corners: its periods and half-turn
// centre are found on its surface all the same.
TEST(SwatchLattice, ATurnedJitteredWeaveRepeatsAsTheWeave) {
  TriMesh weave = make_weave(WeaveOptions{});
  const double angle = 230.0 * 3.14159265358979323846 / 180.0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.003, 0.003);
  for (Vec3& p : weave.positions) {
    p = Vec3(std::cos(angle) * p.x - std::sin(angle) * p.y, std::sin(angle) * p.x + std::cos(angle) * p.y, p.z);
    p += Vec3(jitter(rng), jitter(rng), jitter(rng));
  }
  const std::optional<SwatchLattice> lattice = swatch_lattice(prepare_swatch(weave), 2);
  ASSERT_TRUE(lattice.has_value());
  // The weave's own periods, (2, 0) and (0, 2) pitches, turned: the basis spans that lattice.
  const glm::dvec2 u(std::cos(angle), std::sin(angle)), v(-std::sin(angle), std::cos(angle));
  const auto& [a, b] = lattice->basis;
  for (const glm::dvec2& period : {a, b}) {
    const glm::dvec2 k(glm::dot(period, u) / 2.0, glm::dot(period, v) / 2.0);
    EXPECT_NEAR(k.x, std::round(k.x), 0.02) << period.x << " " << period.y;
    EXPECT_NEAR(k.y, std::round(k.y), 0.02) << period.x << " " << period.y;
  }
  EXPECT_NEAR(std::abs(a.x * b.y - a.y * b.x), 4.0, 0.1);
}

}  // namespace
}  // namespace meshquilt
