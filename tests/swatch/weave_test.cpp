// The weave and wire generators: over and under read back from the geometry, yarns closed and
// apart, the counts and sizes they refuse, and swatches at the edge of what they accept.
#include <gtest/gtest.h>

#include "swatch/weave.h"
#include "swatch_checks.h"

namespace meshquilt {
namespace {

using namespace swatch_checks;

// ---------------------------------------------------------------------------------------------
// Weave.

// Height at which a vertical line through (x, y) meets the faces of one element, averaged over
// the hits (the yarn's top and bottom), or NaN when it misses.
double element_height_at(const TriMesh& m, int32_t element, double x, double y) {
  double sum = 0.0;
  int hits = 0;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != element) continue;
    const Vec3 &a = m.positions[m.triangles[f][0]], &b = m.positions[m.triangles[f][1]], &c = m.positions[m.triangles[f][2]];
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::abs(det) < 1e-15) continue;
    const double u = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
    const double v = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
    sum += a.z + u * (b.z - a.z) + v * (c.z - a.z);
    ++hits;
  }
  return hits ? sum / hits : NAN;
}

// Reads the pattern back from the geometry: at each crossing centre, which yarn is higher.
void check_weave_pattern(const TriMesh& m, const WeaveOptions& o, int warps, int wefts,
                         const std::function<bool(int, int)>& expected_warp_over, bool periodic = true) {
  const Box all = bounds(m);
  for (int i = 0; i < warps; ++i) {
    // Every warp spans the swatch along y, staying in its own column.
    Box b;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.elements[f] == i)
        for (int32_t v : m.triangles[f]) b.add(m.positions[v]);
    EXPECT_NEAR(b.lo.y, all.lo.y, 0.5 * o.pitch) << "warp " << i;
    EXPECT_NEAR(b.hi.y, all.hi.y, 0.5 * o.pitch) << "warp " << i;
    EXPECT_LT(b.extent().x, o.pitch) << "warp " << i;
    EXPECT_GT(b.extent().y, (wefts - 0.5) * o.pitch) << "warp " << i;
  }
  for (int j = 0; j < wefts; ++j) {
    Box b;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.elements[f] == warps + j)
        for (int32_t v : m.triangles[f]) b.add(m.positions[v]);
    EXPECT_NEAR(b.lo.x, all.lo.x, 0.5 * o.pitch) << "weft " << j;
    EXPECT_NEAR(b.hi.x, all.hi.x, 0.5 * o.pitch) << "weft " << j;
    EXPECT_LT(b.extent().y, o.pitch) << "weft " << j;
    EXPECT_GT(b.extent().x, (warps - 0.5) * o.pitch) << "weft " << j;
  }
  // Periodic: shifted by the period, each yarn's end section lands exactly on its start section
  // (its cap ring and cap centre), so tiled copies continue every yarn seamlessly.
  const double L_x = warps * o.pitch, L_y = wefts * o.pitch;
  for (int e = 0; periodic && e < warps + wefts; ++e) {
    const Vec3 shift = e < warps ? Vec3(0, L_y, 0) : Vec3(L_x, 0, 0);
    std::vector<Vec3> verts;
    for (size_t f = 0; f < m.triangles.size(); ++f)
      if (m.elements[f] == e)
        for (int32_t v : m.triangles[f]) verts.push_back(m.positions[v]);
    std::sort(verts.begin(), verts.end(), [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    int matched = 0;
    for (const Vec3& p : verts) {
      for (const Vec3& q : verts) matched += glm::length(p + shift - q) < 1e-9 * o.pitch;
    }
    EXPECT_GE(matched, o.sides + 1) << "yarn " << e;
  }
  int mismatches = 0;
  for (int j = 0; j < wefts; ++j) {
    for (int i = 0; i < warps; ++i) {
      const double x = (i + 0.5) * o.pitch, y = (j + 0.5) * o.pitch;
      const double warp_z = element_height_at(m, i, x, y), weft_z = element_height_at(m, warps + j, x, y);
      ASSERT_FALSE(std::isnan(warp_z) || std::isnan(weft_z)) << "crossing " << i << "," << j;
      mismatches += (warp_z > weft_z) != expected_warp_over(i, j);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

int mod(int a, int n) { return ((a % n) + n) % n; }

TEST(Weave, DefaultsArePlainClosedDisjointYarns) {
  const WeaveOptions o;
  const TriMesh m = make_weave(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {20, true, 2}, "weave_default");
  check_weave_pattern(m, o, 10, 10, [](int i, int j) { return mod(i - j, 2) == 0; });
  check_round_trip(m, "weave_default");
  const Box b = bounds(m);
  EXPECT_NEAR(b.lo.z, -b.hi.z, 1e-9);
  // Yarns end on the period's borders; a cap, perpendicular to its sloping yarn, may lean out by
  // less than the yarn radius.
  EXPECT_NEAR(b.lo.x, 0.0, o.yarn_radius);
  EXPECT_NEAR(b.hi.x, weave_period(o).x, o.yarn_radius);
  EXPECT_NEAR(b.lo.y, 0.0, o.yarn_radius);
  EXPECT_NEAR(b.hi.y, weave_period(o).y, o.yarn_radius);
}

TEST(Weave, SmallPreset) {
  const WeaveOptions o = WeaveOptions::small();
  const TriMesh m = make_weave(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {8, true, 2}, "weave_small");
  check_weave_pattern(m, o, 4, 4, [](int i, int j) { return mod(i - j, 2) == 0; });
  check_round_trip(m, "weave_small");
}

TEST(Weave, Twill23OnTenByTen) {
  WeaveOptions o = WeaveOptions::small();
  o.pattern = twill_pattern(2, 3);
  o.warps = o.wefts = 10;
  const TriMesh m = make_weave(o);
  check_swatch(m, {20, true, 2}, "weave_twill23");
  // Warp over two wefts, under three, each row shifted by one.
  check_weave_pattern(m, o, 10, 10, [](int i, int j) { return mod(i - j, 5) < 2; });
}

TEST(Weave, Satin41OnTenByTen) {
  WeaveOptions o = WeaveOptions::small();
  o.pattern = satin_pattern(4, 1);
  o.warps = o.wefts = 10;
  const TriMesh m = make_weave(o);
  check_swatch(m, {20, true, 2}, "weave_satin41");
  // 5-end satin: step 2 (1 < 2 < 4, coprime to 5); warp over four, under one.
  check_weave_pattern(m, o, 10, 10, [](int i, int j) { return mod(i - 2 * j, 5) < 4; });
  // Interlacings (the one "under" per row) of neighbouring rows are never adjacent.
  for (int j = 0; j < 5; ++j) {
    int under = -1, next = -1;
    for (int i = 0; i < 5; ++i) {
      if (!o.pattern.over(i, j)) under = i;
      if (!o.pattern.over(i, j + 1)) next = i;
    }
    EXPECT_NE(mod(next - under, 5), 1);
    EXPECT_NE(mod(under - next, 5), 1);
  }
}

TEST(Weave, RandomJacquardDesignFromAnImage) {
  // Every local over/under configuration turns up in a random design; the generator's clearance
  // analysis must hold for all of them, which the exact intersection check confirms.
  const fs::path dir = scratch("jacquard");
  const int n = 12;
  std::string pbm = "P1\n" + std::to_string(n) + " " + std::to_string(n) + "\n";
  uint64_t state = 12345;
  std::vector<std::vector<int>> black(n, std::vector<int>(n));
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      black[r][c] = (state >> 33) & 1;
      pbm += black[r][c] ? "1 " : "0 ";
    }
    pbm += "\n";
  }
  std::ofstream(dir / "design.pbm") << pbm;
  WeaveOptions o = WeaveOptions::small();
  o.pattern = parse_weave_pattern((dir / "design.pbm").string());
  const TriMesh m = make_weave(o);
  check_swatch(m, {2 * n, true, 2}, "weave_jacquard");
  // Image row 0 is the top (largest y, the last weft); black puts the warp over.
  check_weave_pattern(m, o, n, n, [&](int i, int j) { return black[n - 1 - j][i] == 1; });
  fs::remove_all(dir);
}

TEST(Weave, RejectsBadCountsAndTouchingYarns) {
  auto with = [](auto change) {
    WeaveOptions o = WeaveOptions::small();
    change(o);
    return error_code([&] { make_weave(o); });
  };
  EXPECT_EQ(with([](WeaveOptions& o) { o.pattern = twill_pattern(2, 3), o.warps = 7; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](WeaveOptions& o) { o.yarn_radius = 0.45; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](WeaveOptions& o) { o.amplitude = 0.15; }), ErrorKind::invalid_option);  // crossings touch
  EXPECT_EQ(with([](WeaveOptions& o) { o.amplitude = 1.5; }), ErrorKind::invalid_option);   // yarn folds
  EXPECT_EQ(with([](WeaveOptions& o) { o.sides = 2; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](WeaveOptions&) {}), std::nullopt);
}

// Sparse crimped wire.

// Bounding box of one element's vertices.
Box element_bounds(const TriMesh& m, int32_t element) {
  Box b;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    if (m.elements[f] == element)
      for (int32_t v : m.triangles[f]) b.add(m.positions[v]);
  return b;
}

// Each wire: centred on its own line at (n + 1/2) pitch, one radius to either side of it,
// the swatch's full length along it, and crimped: its z span is 2 (crimp + radius) within the
// facets' sag.
void check_wires(const TriMesh& m, const WeaveOptions& o, int first_element, int count, bool warp, int length) {
  for (int n = 0; n < count; ++n) {
    SCOPED_TRACE((warp ? "warp " : "weft ") + std::to_string(n));
    const Box b = element_bounds(m, first_element + n);
    const double across_lo = warp ? b.lo.x : b.lo.y, across_hi = warp ? b.hi.x : b.hi.y;
    const double along_lo = warp ? b.lo.y : b.lo.x, along_hi = warp ? b.hi.y : b.hi.x;
    // Section vertices sit at angles 2 pi k / sides from the across direction.
    double lowest_cos = 1.0;
    for (int k = 0; k < o.sides; ++k) lowest_cos = std::min(lowest_cos, std::cos(2.0 * std::numbers::pi * k / o.sides));
    EXPECT_NEAR(across_hi, (n + 0.5) * o.pitch + o.yarn_radius, 1e-9);
    EXPECT_NEAR(across_lo, (n + 0.5) * o.pitch + lowest_cos * o.yarn_radius, 1e-9);
    // Caps lean out by less than a radius past the swatch's borders.
    EXPECT_NEAR(along_lo, 0.0, o.yarn_radius);
    EXPECT_NEAR(along_hi, length * o.pitch, o.yarn_radius);
    EXPECT_GT(b.extent().z, 2.0 * (o.amplitude + o.yarn_radius) * 0.95);
    EXPECT_LE(b.extent().z, 2.0 * (o.amplitude + o.yarn_radius) + 1e-9);
  }
}

TEST(Wire, DefaultIsNineByNineSparseCrimpedPlainWeave) {
  const WeaveOptions o = WeaveOptions::wire();
  const TriMesh m = make_weave(o);
  EXPECT_EQ(m.num_faces(), 21024u);
  check_swatch(m, {18, true, 2}, "wire_default");  // closed tubes, no two touching (brute force)
  check_weave_pattern(m, o, 9, 9, [](int i, int j) { return mod(i - j, 2) == 0; }, false);
  check_round_trip(m, "wire_default");
  // Thin wires several diameters apart: the gap between parallel wires is at least 5 diameters.
  EXPECT_GE(o.pitch - 2.0 * o.yarn_radius, 5.0 * 2.0 * o.yarn_radius);
  check_wires(m, o, 0, 9, true, 9);
  check_wires(m, o, 9, 9, false, 9);
}

TEST(Wire, SmallPresetAndChosenSpacing) {
  const WeaveOptions small = WeaveOptions::small_wire();
  const TriMesh m = make_weave(small);
  EXPECT_LE(m.num_faces(), 2100u);
  check_swatch(m, {10, true, 2}, "wire_small");
  check_wires(m, small, 0, 5, true, 5);
  check_wires(m, small, 5, 5, false, 5);

  // Radius and pitch are independent: a wider spacing and a thinner wire, 7 x 4 wires.
  WeaveOptions o = small;
  o.pitch = 2.5;
  o.yarn_radius = 0.05;
  o.amplitude = 0.2;
  o.warps = 7;
  o.wefts = 4;
  const TriMesh wide = make_weave(o);
  check_swatch(wide, {11, true, 2}, "wire_wide");
  check_weave_pattern(wide, o, 7, 4, [](int i, int j) { return mod(i - j, 2) == 0; }, false);
  check_wires(wide, o, 0, 7, true, 4);
  check_wires(wide, o, 7, 4, false, 7);
}

TEST(Wire, OneDirectionBuildsOnlyThoseWires) {
  for (const WeaveYarns yarns : {WeaveYarns::warps, WeaveYarns::wefts}) {
    const bool warp = yarns == WeaveYarns::warps;
    SCOPED_TRACE(warp ? "warps" : "wefts");
    WeaveOptions o = WeaveOptions::small_wire();
    o.warps = 5;
    o.wefts = 3;
    o.yarns = yarns;
    const TriMesh m = make_weave(o);
    const int count = warp ? 5 : 3;
    check_swatch(m, {count, true, 2}, warp ? "wire_warps" : "wire_wefts");
    // Every element runs in the one direction, across the other direction's full length.
    check_wires(m, o, 0, count, warp, warp ? 3 : 5);
    // Exactly the faces of those wires in the two-direction swatch, in the same order.
    WeaveOptions both = o;
    both.yarns = WeaveYarns::both;
    const TriMesh full = make_weave(both);
    const int32_t first = warp ? 0 : 5;
    std::vector<Vec3> expected, got;
    for (size_t f = 0; f < full.triangles.size(); ++f)
      if (full.elements[f] >= first && full.elements[f] < first + count)
        for (int32_t v : full.triangles[f]) expected.push_back(full.positions[v]);
    for (const Tri& t : m.triangles)
      for (int32_t v : t) got.push_back(m.positions[v]);
    EXPECT_EQ(got, expected);
  }
  // Without crossings the crimp need not clear the other direction: an amplitude the two-way
  // swatch refuses is accepted for one direction.
  WeaveOptions flat = WeaveOptions::small_wire();
  flat.amplitude = 0.05;

  EXPECT_EQ(error_code([&] { make_weave(flat); }), ErrorKind::invalid_option);
  flat.yarns = WeaveYarns::wefts;
  EXPECT_EQ(error_code([&] { make_weave(flat); }), std::nullopt);
}

TEST(Wire, AnyCountOnlyWithoutWholeRepeats) {
  WeaveOptions o = WeaveOptions::small();  // whole repeats required, as before
  o.warps = 5;
  EXPECT_EQ(error_code([&] { make_weave(o); }), ErrorKind::invalid_option);
  o.whole_repeats = false;
  EXPECT_EQ(error_code([&] { make_weave(o); }), std::nullopt);
}


TEST(SizeChecks, WeaveAtTheLimitDoesNotIntersect) {
  for (int segments : {3, 4, 6}) {
    WeaveOptions o = WeaveOptions::small();
    o.segments_per_pitch = segments;
    o.pattern = twill_pattern(1, 2);
    o.warps = o.wefts = 6;
    const WeaveOptions limit = at_acceptance_limit(o, &WeaveOptions::amplitude, 0.3, 0.05, make_weave);
    EXPECT_LT(limit.amplitude, 0.3);
    const TriMesh m = make_weave(limit);
    EXPECT_EQ(intersecting_pairs(m), 0) << "segments " << segments << " amplitude " << limit.amplitude;
  }
}


}  // namespace
}  // namespace meshquilt
