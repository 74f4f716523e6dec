// The ring link graph against an independent count: the signed crossings of one ring's centre
// line through a disk spanning the other (a fan of triangles), on constructed rings and on the
// generator's chain mail, whose 4-in-1 pattern links every inner ring to four others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "inspect/ring_links.h"
#include "mesh/topology.h"
#include "swatch/chainmail.h"

namespace meshquilt {
namespace {

// A circle of `n` points about `centre` in the plane spanned by unit vectors u, w.
std::vector<Vec3> circle(const Vec3& centre, const Vec3& u, const Vec3& w, double radius, int n = 40) {
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n;
    points.push_back(centre + radius * (std::cos(t) * u + std::sin(t) * w));
  }
  return points;
}

// A torus mesh (a ring of wire) around a centre circle, as one element.
TriMesh torus(const Vec3& centre, const Vec3& u, const Vec3& w, double radius, double wire, int element) {
  TriMesh m;
  const int n = 32, k = 8;
  const Vec3 normal = glm::cross(u, w);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const Vec3 out = std::cos(t) * u + std::sin(t) * w;
    for (int j = 0; j < k; ++j) {
      const double s = 2.0 * std::numbers::pi * j / k;
      m.positions.push_back(centre + radius * out + wire * (std::cos(s) * out + std::sin(s) * normal));
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      const int a = i * k + j, b = ((i + 1) % n) * k + j, c = ((i + 1) % n) * k + (j + 1) % k, d = i * k + (j + 1) % k;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
      m.elements.push_back(element);
      m.elements.push_back(element);
    }
  return m;
}

// Signed crossings of polygon b through the fan of triangles spanning polygon a from its
// centroid (a disk for a star-shaped a): an independent linking number.
int crossings(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  Vec3 c(0.0);
  for (const Vec3& p : a) c += p;
  c /= static_cast<double>(a.size());
  int total = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const Vec3 p0 = c, p1 = a[i], p2 = a[(i + 1) % a.size()];
    const Vec3 normal = glm::cross(p1 - p0, p2 - p0);  // the fan's orientation follows a's
    for (size_t j = 0; j < b.size(); ++j) {
      const Vec3 q0 = b[j], q1 = b[(j + 1) % b.size()];
      const double d0 = glm::dot(q0 - p0, normal), d1 = glm::dot(q1 - p0, normal);
      if ((d0 > 0.0) == (d1 > 0.0) || d0 == d1) continue;
      const Vec3 x = q0 + (d0 / (d0 - d1)) * (q1 - q0);
      const Vec3 e0 = glm::cross(p1 - p0, x - p0), e1 = glm::cross(p2 - p1, x - p1), e2 = glm::cross(p0 - p2, x - p2);
      if (glm::dot(e0, normal) >= 0.0 && glm::dot(e1, normal) >= 0.0 && glm::dot(e2, normal) >= 0.0)
        total += d1 > d0 ? 1 : -1;
    }
  }
  return total;
}

const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);

TEST(RingLinks, LinkingNumberOfConstructedPairs) {
  const std::vector<Vec3> a = circle(Vec3(0.0), X, Y, 1.0);
  // A Hopf link: the second circle in the x-z plane through a's disk.
  const std::vector<Vec3> hopf = circle(Vec3(1.05, 0.13, 0), X, Z, 1.0);
  EXPECT_NEAR(std::abs(linking_number(a, hopf)), 1.0, 1e-9);
  EXPECT_NEAR(linking_number(a, hopf), crossings(a, hopf), 1e-9);
  EXPECT_NEAR(linking_number(hopf, a), linking_number(a, hopf), 1e-9);
  // Unlinked though nearly touching: the second circle passes just outside a.
  const std::vector<Vec3> outside = circle(Vec3(2.02, 0, 0), X, Z, 1.0);
  EXPECT_NEAR(linking_number(a, outside), 0.0, 1e-9);
  EXPECT_EQ(crossings(a, outside), 0);
  // Parallel and apart, and side by side in one plane.
  EXPECT_NEAR(linking_number(a, circle(Vec3(0, 0, 0.1), X, Y, 1.0)), 0.0, 1e-9);
  EXPECT_NEAR(linking_number(a, circle(Vec3(2.5, 0, 0), X, Y, 1.0)), 0.0, 1e-9);
}

TEST(RingLinks, RandomPairsAgreeWithCrossings) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int linked = 0, unlinked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto random_frame = [&](Vec3& u, Vec3& w) {
      Vec3 n;
      do n = Vec3(unit(rng), unit(rng), unit(rng));
      while (glm::length(n) < 0.1);
      n = glm::normalize(n);
      u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? X : Y));
      w = glm::cross(n, u);
    };
    Vec3 u1, w1, u2, w2;
    random_frame(u1, w1);
    random_frame(u2, w2);
    const std::vector<Vec3> a = circle(Vec3(0.0), u1, w1, 1.0, 30);
    const std::vector<Vec3> b = circle(1.6 * Vec3(unit(rng), unit(rng), unit(rng)), u2, w2, 0.6 + 0.8 * std::abs(unit(rng)), 30);
    const double lk = linking_number(a, b);
    EXPECT_NEAR(lk, std::round(lk), 1e-6) << trial;
    EXPECT_EQ(static_cast<int>(std::lround(lk)), crossings(a, b)) << trial;
    (std::lround(lk) != 0 ? linked : unlinked)++;
  }
  EXPECT_GT(linked, 30);  // both cases are exercised
  EXPECT_GT(unlinked, 30);
}

TEST(RingLinks, AChainOfTorusRings) {
  // Five rings, each through the next, alternately in the x-y and x-z planes.
  TriMesh chain;
  for (int r = 0; r < 5; ++r) {
    const TriMesh ring = torus(Vec3(1.5 * r, 0, 0), X, r % 2 ? Z : Y, 1.0, 0.1, r);
    chain = join_elements({chain, ring});
  }
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(chain, &elements);
  ASSERT_EQ(elements, 5);
  const RingLinks links = ring_links(chain, face_element, elements);
  EXPECT_EQ(links.links.size(), 4u);
  EXPECT_EQ(links.pieces, 1);
  EXPECT_EQ(links.largest_piece_share, 1.0);
  EXPECT_EQ(links.loose_rings, 0);
  EXPECT_NEAR(links.median_radius, 1.0, 0.02);
  ASSERT_GE(links.histogram.size(), 3u);
  EXPECT_EQ(links.histogram[1], 2);  // the ends
  EXPECT_EQ(links.histogram[2], 3);
}

TEST(RingLinks, TheRingsNearAPointOfAChainWithTheirLinks) {
  // Five rings at x = 0, 1.5, 3, 4.5, 6, each through the next; rings of radius 2 apart from them.
  TriMesh chain;
  for (int r = 0; r < 5; ++r) chain = join_elements({chain, torus(Vec3(1.5 * r, 0, 0), X, r % 2 ? Z : Y, 1.0, 0.1, r)});
  chain = join_elements({chain, torus(Vec3(0, 20, 0), X, Y, 2.0, 0.1, 5)});
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(chain, &elements);
  const RingLinks links = ring_links(chain, face_element, elements);
  const std::vector<RingCentreLine> lines = ring_centre_lines(chain, face_element, elements);

  // Within 1.6 of the first ring's centre: the first (one link) and the second (two).
  const RingsNear end = rings_near(links, lines, {Vec3(0, 0, 0)}, 1.6);
  EXPECT_EQ(end.rings, 2);
  EXPECT_EQ(end.histogram, (std::vector<int32_t>{0, 1, 1}));
  EXPECT_EQ(end.linked_to_3_share, 0.0);
  EXPECT_EQ(end.loose_rings, 0);
  EXPECT_NEAR(end.median_radius, 1.0, 0.02);

  // Two points: the chain's middle ring and the loose large one.
  const RingsNear two = rings_near(links, lines, {Vec3(3, 0, 0), Vec3(0, 20, 0)}, 0.5);
  EXPECT_EQ(two.rings, 2);
  EXPECT_EQ(two.histogram, (std::vector<int32_t>{1, 0, 1}));
  EXPECT_EQ(two.loose_rings, 1);
  EXPECT_NEAR(two.radius_p10, 1.0, 0.02);
  EXPECT_NEAR(two.radius_p90, 2.0, 0.04);

  EXPECT_EQ(rings_near(links, lines, {Vec3(0, -50, 0)}, 1.0).rings, 0);
}

TEST(RingLinks, RadiusPercentilesOfRingsOfTenSizes) {
  // Ten loose rings of radius 1, 2, ..., 10: the 10th and 90th percentiles are rings 2 and 9.
  TriMesh rings;
  for (int r = 1; r <= 10; ++r) rings = join_elements({rings, torus(Vec3(25.0 * r, 0, 0), X, Y, r, 0.1, r)});
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(rings, &elements);
  ASSERT_EQ(elements, 10);
  const RingLinks links = ring_links(rings, face_element, elements);
  EXPECT_EQ(links.links.size(), 0u);
  EXPECT_NEAR(links.radius_p10, 2.0, 0.04);
  EXPECT_NEAR(links.radius_p90, 9.0, 0.18);
}

TEST(RingLinks, AspectOfRoundAndOvalRings) {
  // A round ring and rings drawn on ellipses of axes 1.5 x 1 and 1 x 2: aspects 1, 1.5, 2.
  TriMesh rings = torus(Vec3(0.0), X, Y, 1.0, 0.1, 0);
  rings = join_elements({rings, torus(Vec3(10, 0, 0), 1.5 * X, Y, 1.0, 0.1, 1)});
  rings = join_elements({rings, torus(Vec3(20, 0, 0), Z, 2.0 * Y, 1.0, 0.1, 2)});
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(rings, &elements);
  ASSERT_EQ(elements, 3);
  const std::vector<RingCentreLine> lines = ring_centre_lines(rings, face_element, elements);
  std::vector<double> aspects;
  for (const RingCentreLine& line : lines) aspects.push_back(line.aspect);
  std::sort(aspects.begin(), aspects.end());
  EXPECT_NEAR(aspects[0], 1.0, 0.01);
  EXPECT_NEAR(aspects[1], 1.5, 0.03);
  EXPECT_NEAR(aspects[2], 2.0, 0.08);  // 24 angular bins round the ends of the long axis
  const RingLinks links = ring_links(rings, face_element, elements);
  EXPECT_NEAR(links.median_aspect, 1.5, 0.03);
  EXPECT_NEAR(links.aspect_p90, 2.0, 0.08);
}

TEST(RingLinks, TheGeneratorsChainMailLinksInnerRingsToFour) {
  ChainmailOptions o = ChainmailOptions::small();
  o.rows = 6;
  o.columns = 5;
  const TriMesh mail = make_chainmail(o);
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(mail, &elements);
  const RingLinks links = ring_links(mail, face_element, elements);
  EXPECT_EQ(links.pieces, 1);
  EXPECT_EQ(links.loose_rings, 0);
  // Every link agrees with the independent count, and no ring links more than four.
  const std::vector<RingCentreLine> lines = ring_centre_lines(mail, face_element, elements);
  for (const auto& [a, b] : links.links) EXPECT_NE(crossings(lines[a].points, lines[b].points), 0) << a << " " << b;
  int four = 0;
  for (int32_t k : links.links_per_ring) {
    EXPECT_LE(k, 4);
    four += k == 4;
  }
  EXPECT_GT(four, elements / 3);  // the inner rings
}

}  // namespace
}  // namespace meshquilt
