// The chain mail generator: closed, disjoint, linked rings that tile with their period, and the
// sizes it refuses; and the independent intersection check itself.
#include <gtest/gtest.h>

#include "swatch/chainmail.h"
#include "swatch_checks.h"

namespace meshquilt {
namespace {

using namespace swatch_checks;

// ---------------------------------------------------------------------------------------------
// The checker must see an intersection when there is one.

TEST(SwatchChecks, IntersectionCheckFindsOverlappingRings) {
  ChainmailOptions o = ChainmailOptions::small();
  o.rows = 2;
  o.columns = 1;
  TriMesh one = make_chainmail(o);
  TriMesh two = one;
  const auto offset = static_cast<int32_t>(one.positions.size());
  for (const Vec3& p : one.positions) two.positions.push_back(p + Vec3(0.05, 0.0, 0.0));
  for (const Tri& t : one.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (int32_t e : one.elements) two.elements.push_back(e + 2);
  EXPECT_GT(intersecting_pairs(two), 0);
  EXPECT_EQ(intersecting_pairs(one), 0);
}

// ---------------------------------------------------------------------------------------------
// Chain mail.

// Does some edge of element b cross the plane of element a inside a's hole? The hole's disk is
// found from a's vertices alone: centroid, normal = axis of least spread, radius = the smallest
// in-plane distance of a vertex from the centroid.
bool threads_hole(const TriMesh& m, int32_t a, int32_t b) {
  Vec3 centroid(0.0);
  int n = 0;
  std::vector<int32_t> verts;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != a) continue;
    for (int32_t v : m.triangles[f]) verts.push_back(v);
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (int32_t v : verts) centroid += m.positions[v], ++n;
  centroid /= static_cast<double>(n);
  // Power iteration on (trace I - covariance) finds the covariance's smallest axis.
  double cov[3][3] = {};
  for (int32_t v : verts) {
    const Vec3 d = m.positions[v] - centroid;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) cov[i][j] += d[i] * d[j];
  }
  const double trace = cov[0][0] + cov[1][1] + cov[2][2];
  Vec3 normal(0.3, 0.2, 1.0);
  for (int it = 0; it < 200; ++it) {
    Vec3 next(0.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) next[i] += ((i == j ? trace : 0.0) - cov[i][j]) * normal[j];
    normal = glm::normalize(next);
  }
  double hole = INFINITY;
  for (int32_t v : verts) {
    const Vec3 d = m.positions[v] - centroid;
    hole = std::min(hole, glm::length(d - glm::dot(d, normal) * normal));
  }
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != b) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = m.positions[m.triangles[f][k]], q = m.positions[m.triangles[f][(k + 1) % 3]];
      const double dp = glm::dot(p - centroid, normal), dq = glm::dot(q - centroid, normal);
      if ((dp < 0.0) == (dq < 0.0)) continue;
      const Vec3 x = p + (dp / (dp - dq)) * (q - p);
      if (glm::length(x - centroid) < hole) return true;
    }
  }
  return false;
}

void check_chainmail_links(const TriMesh& m, const ChainmailOptions& o) {
  // Expected links straight from the 4-in-1 rule: ring (c, r) links the rings of rows r +- 1
  // whose centres lie half a pitch to either side; odd rows are shifted by half a pitch.
  int expected = 0, found = 0;
  for (int r = 0; r < o.rows; ++r) {
    for (int c = 0; c < o.columns; ++c) {
      int degree = 0;
      for (int r2 = 0; r2 < o.rows; ++r2) {
        for (int c2 = 0; c2 < o.columns; ++c2) {
          if (r2 == r && c2 == c) continue;
          const double dx = (c2 + 0.5 * (r2 % 2)) - (c + 0.5 * (r % 2));
          const bool linked = std::abs(r2 - r) == 1 && std::abs(std::abs(dx) - 0.5) < 1e-9;
          const bool threads = threads_hole(m, r * o.columns + c, r2 * o.columns + c2);
          EXPECT_EQ(threads, linked) << "ring (" << c << "," << r << ") and (" << c2 << "," << r2 << ")";
          expected += linked;
          found += threads;
          degree += threads;
        }
      }
      const bool interior = r > 0 && r + 1 < o.rows && c > 0 && c + 1 < o.columns;
      if (interior) {
        EXPECT_EQ(degree, 4) << "interior ring (" << c << "," << r << ")";
      }
    }
  }
  EXPECT_EQ(found, expected);
}

TEST(Chainmail, DefaultsAreClosedDisjointLinkedRings) {
  const ChainmailOptions o;
  const TriMesh m = make_chainmail(o);
  EXPECT_GE(m.num_faces(), 2000u);
  EXPECT_LE(m.num_faces(), 20000u);
  check_swatch(m, {o.rows * o.columns, true, 0}, "chainmail_default");
  check_chainmail_links(m, o);
  check_round_trip(m, "chainmail_default");
  // Centred on z = 0 and periodic: the lattice's period is whole rings.
  const Box b = bounds(m);
  EXPECT_NEAR(b.lo.z, -b.hi.z, 1e-9);
  EXPECT_DOUBLE_EQ(chainmail_period(o).x, o.columns * o.pitch_x);
}

TEST(Chainmail, SmallPreset) {
  const ChainmailOptions o = ChainmailOptions::small();
  const TriMesh m = make_chainmail(o);
  EXPECT_GE(m.num_faces(), 300u);
  EXPECT_LE(m.num_faces(), 2000u);
  check_swatch(m, {o.rows * o.columns, true, 0}, "chainmail_small");
  check_chainmail_links(m, o);
  check_round_trip(m, "chainmail_small");
}

// Periodic: copies shifted by the period neither touch the swatch nor fail to link with it.
TEST(Chainmail, TilesWithItsPeriod) {
  const ChainmailOptions o = ChainmailOptions::small();
  const TriMesh m = make_chainmail(o);
  const glm::dvec2 period = chainmail_period(o);
  const int count = o.rows * o.columns;
  for (const Vec3 shift : {Vec3(period.x, 0, 0), Vec3(0, period.y, 0), Vec3(period.x, period.y, 0)}) {
    TriMesh both = m;
    const auto offset = static_cast<int32_t>(m.positions.size());
    for (const Vec3& p : m.positions) both.positions.push_back(p + shift);
    for (const Tri& t : m.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    for (int32_t e : m.elements) both.elements.push_back(e + count);
    EXPECT_EQ(intersecting_pairs(both), 0);
  }
  // Shifted up by the period, row 0 of the copy sits where row `rows` would: the last row's
  // ring (c, rows-1) links copy rings (c, 0) and (c+1, 0), rows being odd/even alternately.
  TriMesh both = m;
  const auto offset = static_cast<int32_t>(m.positions.size());
  for (const Vec3& p : m.positions) both.positions.push_back(p + Vec3(0, period.y, 0));
  for (const Tri& t : m.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (int32_t e : m.elements) both.elements.push_back(e + count);
  const int last = (o.rows - 1) * o.columns;
  EXPECT_TRUE(threads_hole(both, last + 0, count + 0));
  EXPECT_TRUE(threads_hole(both, last + 0, count + 1));
  EXPECT_FALSE(threads_hole(both, last + 0, count + 2));
}


TEST(Chainmail, RejectsSizesThatWouldTouchOrNotLink) {
  auto with = [](auto change) {
    ChainmailOptions o = ChainmailOptions::small();
    change(o);
    return error_code([&] { make_chainmail(o); });
  };
  EXPECT_EQ(with([](ChainmailOptions& o) { o.wire_radius = 0.3; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.rows = 3; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.columns = 0; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.pitch_y = 2.5; }), ErrorKind::invalid_option);  // rows no longer link
  EXPECT_EQ(with([](ChainmailOptions& o) { o.tilt_degrees = 5.0; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions& o) { o.wire_segments = 2; }), ErrorKind::invalid_option);
  EXPECT_EQ(with([](ChainmailOptions&) {}), std::nullopt);
}


TEST(SizeChecks, ChainmailAtTheLimitDoesNotIntersect) {
  for (int segments : {8, 12, 24}) {
    ChainmailOptions o = ChainmailOptions::small();
    o.ring_segments = segments;
    const ChainmailOptions limit = at_acceptance_limit(o, &ChainmailOptions::wire_radius, 0.1, 0.4, make_chainmail);
    EXPECT_GT(limit.wire_radius, 0.15) << "segments " << segments;
    const TriMesh m = make_chainmail(limit);
    EXPECT_EQ(intersecting_pairs(m), 0) << "segments " << segments << " wire " << limit.wire_radius;
  }
}

}  // namespace
}  // namespace meshquilt
