// Lattice classes: which swatch elements are copies of one another at a period, and which stand
// alone in the pattern (the step would pair them with nothing), on patterns whose answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "device.h"
#include "mesh/topology.h"
#include "quilt/lattice_classes.h"
#include "quilt/planar_quilting.h"
#include "quilt/swatch_lattice.h"
#include "spatial/intersecting_pairs.h"
#include "swatch/chainmail.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

TriMesh tetrahedron(const Vec3& at, double size) {
  TriMesh m;
  m.positions = {at, at + Vec3(size, 0, 0), at + Vec3(0, size, 0), at + Vec3(0, 0, size)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// n x n sites `spacing` apart, each holding a tetrahedron and, with `second`, another one moved
// by it.
TriMesh sites(int n, double spacing, const Vec3* second = nullptr) {
  std::vector<TriMesh> parts;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 at(i * spacing, j * spacing, 0.0);
      parts.push_back(tetrahedron(at, 1.0));
      if (second) parts.push_back(tetrahedron(at + *second, 1.0));
    }
  return join_elements(parts);
}

struct Classes {
  QuiltSwatch swatch;
  std::optional<SwatchLattice> lattice;
  std::vector<LatticeClass> classes;
};

Classes classes_of(const TriMesh& mesh) {
  Classes c{prepare_swatch(mesh), std::nullopt, {}};
  c.lattice = swatch_lattice(c.swatch, 1);
  if (!c.lattice) return c;
  c.classes = lattice_classes(c.swatch, *c.lattice, 0.5 * c.swatch.mean_edge, 1e-6 * c.swatch.mean_edge);
  return c;
}

TEST(LatticeClasses, ApartSitesAreOneClassThatStandsAlone) {
  const Classes c = classes_of(sites(4, 3.0));
  ASSERT_TRUE(c.lattice);
  ASSERT_EQ(c.classes.size(), 1u);
  EXPECT_TRUE(c.classes[0].alone);
}

TEST(LatticeClasses, ElementsThatOverlapAnotherDoNotStandAlone) {
  // A second tetrahedron a twentieth of an edge beside each: the step would pair the two.
  const Vec3 beside(0.05, 0.0, 0.0);
  const Classes c = classes_of(sites(4, 3.0, &beside));
  ASSERT_TRUE(c.lattice);
  ASSERT_EQ(c.classes.size(), 2u);
  EXPECT_FALSE(c.classes[0].alone);
  EXPECT_FALSE(c.classes[1].alone);
  // Two apart by more than the pairing range stand alone again.
  const Vec3 far(1.5, 1.5, 0.0);
  const Classes apart = classes_of(sites(4, 5.0, &far));
  ASSERT_TRUE(apart.lattice);
  ASSERT_EQ(apart.classes.size(), 2u);
  EXPECT_TRUE(apart.classes[0].alone && apart.classes[1].alone);
}

// Every swatch element is its class's element moved by a period; classes are not copies of each
// other.
void expect_partition(const Classes& c) {
  const auto centroid = [](const TriMesh& m) {
    Vec3 s(0.0);
    for (const Vec3& p : m.positions) s += p;
    return s / static_cast<double>(m.positions.size());
  };
  for (const TriMesh& e : c.swatch.elements) {
    int matches = 0;
    for (const LatticeClass& cls : c.classes) {
      const TriMesh& r = c.swatch.elements[cls.element];
      const glm::dvec2 d = glm::dvec2(centroid(e) - centroid(r));
      const glm::dvec2 k = lattice_coordinates(d, c.lattice->basis);
      if (glm::distance(k, glm::round(k)) > 1e-6) continue;
      bool same = e.positions.size() == r.positions.size();
      for (size_t v = 0; same && v < e.positions.size(); ++v)
        same = glm::distance(e.positions[v], r.positions[v] + Vec3(d, 0.0)) < 1e-6 * c.swatch.mean_edge;
      matches += same;
    }
    EXPECT_EQ(matches, 1);
  }
}

TEST(LatticeClasses, ChainMailRingsStandAloneAndYarnsDoNot) {
  const Classes mail = classes_of(make_chainmail(ChainmailOptions::small()));
  ASSERT_TRUE(mail.lattice);
  ASSERT_FALSE(mail.classes.empty());
  EXPECT_LT(mail.classes.size(), mail.swatch.elements.size());
  for (const LatticeClass& c : mail.classes) EXPECT_TRUE(c.alone) << "ring " << c.element;
  expect_partition(mail);
  // A yarn moved by a period along itself lies on itself.
  const Classes twill = classes_of(make_weave([] {
    WeaveOptions o;
    o.pattern = twill_pattern(2, 2);
    return o;
  }()));
  ASSERT_TRUE(twill.lattice);
  for (const LatticeClass& c : twill.classes) EXPECT_FALSE(c.alone) << "yarn " << c.element;
}

// A box from lo to hi, as a closed element.
TriMesh box(const Vec3& lo, const Vec3& hi) {
  TriMesh m;
  for (int k = 0; k < 8; ++k) m.positions.emplace_back(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

// Bars along x and bars along y crossing through each other beside every site's centre: each
// stands alone (no bar is close to another along its length), so the plane is filled, and the clean-up must still
// find every crossing: the sample of the pattern shows them, and the whole plane is cleaned.
TEST(LatticeFill, APatternWhoseElementsCrossIsCleanedEverywhere) {
  std::vector<TriMesh> parts;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const Vec3 at(3.0 * i, 3.0 * j, 0.0);
      parts.push_back(box(at + Vec3(-1.0, -0.1, -0.1), at + Vec3(1.0, 0.1, 0.1)));
      parts.push_back(box(at + Vec3(0.2, -1.0, -0.05), at + Vec3(0.4, 1.0, 0.15)));
    }
  const TriMesh swatch = join_elements(parts);
  const Classes c = classes_of(swatch);
  ASSERT_TRUE(c.lattice);
  ASSERT_EQ(c.classes.size(), 2u);
  ASSERT_TRUE(c.classes[0].alone && c.classes[1].alone);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  PlanarQuiltOptions options;
  options.width = options.height = 3.0;
  QuiltStats stats;
  const TriMesh plane = quilt_plane(swatch, *device, options, &stats);
  EXPECT_GT(stats.filled_elements, 100);
  EXPECT_EQ(stats.patches, 0);
  // Every site loses one of its two bars.
  EXPECT_EQ(stats.dropped_intersecting, stats.filled_elements / 2);
  const FaceIntersections met = find_intersecting_faces(plane, plane.elements);
  EXPECT_TRUE(met.different_elements.empty());
}

// Over a plane a filled pattern holds every ring the patch step places at the same place, and
// the rings the step missed lie at the plane's edge; none meets another.
TEST(LatticeFill, APlaneHoldsTheRingsOfTheStep) {
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  auto device = engine::open_device(engine::BackendChoice::cpu);
  PlanarQuiltOptions options;
  options.width = options.height = 3.0;
  QuiltStats filled_stats, stepped_stats;
  const TriMesh filled = quilt_plane(swatch, *device, options, &filled_stats);
  options.fill_margin = 0.0;
  const TriMesh stepped = quilt_plane(swatch, *device, options, &stepped_stats);
  const std::vector<TriMesh> rings = split_elements(filled), step_rings = split_elements(stepped);
  EXPECT_EQ(filled_stats.patches, 0);
  EXPECT_EQ(filled_stats.filled_elements, static_cast<int>(rings.size()));
  EXPECT_EQ(stepped_stats.filled_elements, 0);
  ASSERT_GE(rings.size(), step_rings.size());
  const auto centre = [](const TriMesh& m) {
    Vec3 s(0.0);
    for (const Vec3& p : m.positions) s += p;
    return s / static_cast<double>(m.positions.size());
  };
  std::vector<uint8_t> matched(rings.size(), 0);
  for (const TriMesh& r : step_rings) {
    size_t best = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < rings.size(); ++k)
      if (const double d = glm::distance(centre(r), centre(rings[k])); d < nearest) nearest = d, best = k;
    EXPECT_LT(nearest, 1e-6);
    matched[best] = 1;
  }
  const Box3 plane = bounding_box(filled.positions);
  const QuiltSwatch prepared = prepare_swatch(swatch);
  double ring_size = 0.0;
  for (const Rect2& b : prepared.element_bounds)
    ring_size = std::max(ring_size, std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y));
  for (size_t k = 0; k < rings.size(); ++k) {
    if (matched[k]) continue;
    const Vec3 c = centre(rings[k]);
    const double to_edge = std::min({c.x - plane.lo.x, plane.hi.x - c.x, c.y - plane.lo.y, plane.hi.y - c.y});
    EXPECT_LT(to_edge, ring_size) << "a ring inside the plane that the step did not place";
  }
  const FaceIntersections met = find_intersecting_faces(filled, filled.elements);
  EXPECT_TRUE(met.different_elements.empty());
  EXPECT_TRUE(met.same_element.empty());
}

}  // namespace
}  // namespace meshquilt
