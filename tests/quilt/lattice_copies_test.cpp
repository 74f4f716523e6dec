// Lattice copies: what counts as an element already there, and that skipping the step for such
// elements gives the elements the full step gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "device.h"
#include "mesh/topology.h"
#include "quilt/lattice_copies.h"
#include "quilt/planar_quilting.h"
#include "quilt/swatch_lattice.h"
#include "spatial/closest_point.h"
#include "swatch/chainmail.h"

namespace meshquilt {
namespace {

TriMesh tetrahedron(const Vec3& at) {
  TriMesh m;
  m.positions = {at, at + Vec3(1, 0, 0), at + Vec3(0, 1, 0), at + Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// The same faces with the vertices stored in another order.
TriMesh renumbered(const TriMesh& m, uint32_t seed) {
  std::vector<int32_t> order(m.positions.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  TriMesh out;
  out.positions.resize(m.positions.size());
  for (size_t v = 0; v < order.size(); ++v) out.positions[order[v]] = m.positions[v];
  for (const Tri& t : m.triangles) out.triangles.push_back({order[t[0]], order[t[1]], order[t[2]]});
  return out;
}

TEST(LatticeCopies, SameElementUpToRenumberingAndTolerance) {
  const TriMesh a = tetrahedron(Vec3(2, 3, 0));
  for (uint32_t seed = 0; seed < 8; ++seed) EXPECT_TRUE(same_element(a, renumbered(a, seed), 1e-9));
  TriMesh moved = a;
  moved.positions[3].z += 1e-7;
  EXPECT_TRUE(same_element(a, moved, 1e-6));
  EXPECT_FALSE(same_element(a, moved, 1e-8));
  TriMesh flipped = a;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);  // one face wound the other way
  EXPECT_FALSE(same_element(a, flipped, 1e-6));
  TriMesh merged = a;  // two corners made one: the renumbering must be one to one
  merged.triangles[3] = {1, 2, 2};
  TriMesh other = a;
  other.triangles[3] = {1, 2, 3};
  EXPECT_FALSE(same_element(merged, other, 1e-6));
}

TEST(LatticeCopies, EachLayerElementStandsForOneInput) {
  std::vector<PlaneElement> layer(3);
  layer[0].mesh = tetrahedron(Vec3(0, 0, 0));
  layer[1].mesh = tetrahedron(Vec3(5, 0, 0));
  layer[1].pinned = {1, 0, 0, 0};  // a part of an element: never a copy
  layer[2].mesh = tetrahedron(Vec3(9, 0, 0));
  layer[2].alive = false;
  for (PlaneElement& e : layer) e.bounds = xy_bounds(e.mesh);
  const std::vector<TriMesh> inputs = {renumbered(tetrahedron(Vec3(0, 0, 0)), 3), tetrahedron(Vec3(0, 0, 0)),
                                       tetrahedron(Vec3(5, 0, 0)), tetrahedron(Vec3(9, 0, 0)),
                                       tetrahedron(Vec3(0, 0.001, 0))};
  EXPECT_EQ(lattice_copies(layer, {0, 1, 2}, inputs, 1e-6), (std::vector<int32_t>{0, -1, -1, -1, -1}));
}

// The pattern's contacts against a brute-force distance: element a moved by a period touches b
// exactly where some vertex of it lies within reach of b's faces.
TEST(LatticeCopies, ContactsAgreeWithBruteForceDistances) {
  ChainmailOptions o = ChainmailOptions::small();
  const QuiltSwatch swatch = prepare_swatch(make_chainmail(o));
  const std::optional<SwatchLattice> lattice = swatch_lattice(swatch, 1);
  ASSERT_TRUE(lattice);
  const double reach = 0.5 * swatch.mean_edge;
  LatticeContacts contacts(swatch, lattice->basis, reach);
  int touching = 0, apart = 0;
  for (int32_t a = 0; a < static_cast<int32_t>(swatch.elements.size()); ++a)
    for (int32_t b = 0; b < static_cast<int32_t>(swatch.elements.size()); ++b)
      for (int64_t k0 = -1; k0 <= 1; ++k0)
        for (int64_t k1 = -1; k1 <= 1; ++k1) {
          const glm::dvec2 q = double(k0) * lattice->basis[0] + double(k1) * lattice->basis[1];
          bool near = false;
          for (const Vec3& v : swatch.elements[a].positions) {
            const Vec3 p = v + Vec3(q, 0.0);
            const TriMesh& m = swatch.elements[b];
            for (const Tri& t : m.triangles)
              near = near || closest_point_on_triangle(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]).distance <= reach;
            if (near) break;
          }
          EXPECT_EQ(contacts.touches(a, b, {k0, k1}), near) << a << " " << b << " " << k0 << " " << k1;
          (near ? touching : apart) += 1;
        }
  EXPECT_GT(touching, 0);  // itself at period zero, at least
  EXPECT_GT(apart, 0);
}

// Quilted with and without the skipping, a chain mail has the same rings at the same places.
TEST(LatticeCopies, SkippingGivesTheElementsOfTheFullStep) {
  const TriMesh swatch = make_chainmail(ChainmailOptions::small());
  auto device = engine::open_device(engine::BackendChoice::cpu);
  PlanarQuiltOptions options;
  options.width = options.height = 3.0;
  options.seed = 4;
  options.fill_margin = 0.0;  // every ring through the step
  QuiltStats fast_stats, full_stats;
  const TriMesh fast = quilt_plane(swatch, *device, options, &fast_stats);
  options.step.skip_lattice_copies = false;
  const TriMesh full = quilt_plane(swatch, *device, options, &full_stats);
  EXPECT_TRUE(fast_stats.on_lattice);
  EXPECT_GT(fast_stats.merges.lattice_copies, 0);
  EXPECT_EQ(full_stats.merges.lattice_copies, 0);
  const auto centres = [](const TriMesh& m) {
    std::vector<Vec3> c;
    for (const TriMesh& e : split_elements(m)) {
      Vec3 sum(0.0);
      for (const Vec3& p : e.positions) sum += p;
      c.push_back(sum / static_cast<double>(e.positions.size()));
    }
    return c;
  };
  ASSERT_GT(fast.num_faces(), 0u);
  EXPECT_EQ(fast.num_faces(), full.num_faces());
  const std::vector<Vec3> a = centres(fast), b = centres(full);
  ASSERT_EQ(a.size(), b.size());
  for (const Vec3& p : a) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec3& q : b) nearest = std::min(nearest, glm::distance(p, q));
    EXPECT_LT(nearest, 1e-6) << "a ring at " << p.x << ", " << p.y << " only where copies skip the step";
  }
}

}  // namespace
}  // namespace meshquilt
