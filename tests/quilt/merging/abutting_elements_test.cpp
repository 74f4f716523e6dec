// Joining elements that meet face to face: boxes end to end become one closed box, checked by
// counts, topology and the enclosed volume (divergence theorem, written here); anything else is
// left as it was.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "mesh/topology.h"
#include "quilt/merging/abutting_elements.h"
#include "support/boxes.h"

namespace meshquilt {
namespace {

using test::box;

double enclosed_volume(const TriMesh& m) {
  double six = 0.0;
  for (const Tri& t : m.triangles) six += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]]));
  return six / 6.0;
}

int32_t element_count(const TriMesh& m) {
  int32_t n = 0;
  for (int32_t e : m.elements) n = std::max(n, e + 1);
  return n;
}

TEST(AbuttingElements, BoxesEndToEndBecomeOneClosedBox) {
  // Three unit boxes in a row, the middle one's near face moved by less than the tolerance
  // (1e-6 x the layer's diagonal of about 6.1), and a fourth apart.
  TriMesh layer = join_elements({box(Vec3(0.0), Vec3(1.0)), box(Vec3(1.0 + 2e-6, 0.0, 0.0), Vec3(2.0, 1.0, 1.0)),
                                 box(Vec3(5.0, 0.0, 0.0), Vec3(6.0, 1.0, 1.0)), box(Vec3(2.0, 0.0, 0.0), Vec3(3.0, 1.0, 1.0))});
  layer.sources = std::vector<int32_t>(layer.num_faces(), 7);
  ASSERT_EQ(enclosed_volume(box(Vec3(0.0), Vec3(1.0))), 1.0);  // outward faces
  EXPECT_EQ(join_abutting_elements(layer, 1e-6), 2);
  EXPECT_EQ(layer.num_faces(), 48u - 8u);
  EXPECT_EQ(layer.num_vertices(), 32u - 8u);
  EXPECT_EQ(layer.sources.size(), layer.num_faces());
  EXPECT_EQ(element_count(layer), 2);  // consecutive: the row, then the box apart
  const std::vector<TriMesh> parts = split_elements(layer);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_TRUE(inspect_surface(parts[0]).closed_manifold());
  EXPECT_EQ(inspect_surface(parts[0]).components, 1);
  EXPECT_NEAR(enclosed_volume(parts[0]), 3.0, 1e-9);  // the first box's corners are kept
  EXPECT_NEAR(enclosed_volume(parts[1]), 1.0, 1e-12);
  EXPECT_EQ(parts[1].positions.front(), Vec3(5.0, 0.0, 0.0));
}

// Face f of `mesh`, reversed, as a mesh of its own.
TriMesh lone_triangle(const TriMesh& mesh, size_t f) {
  TriMesh m;
  for (int k = 0; k < 3; ++k) m.positions.push_back(mesh.positions[mesh.triangles[f][2 - k]]);
  m.triangles.push_back({0, 1, 2});
  return m;
}

TEST(AbuttingElements, LeavesElementsThatOnlyTouchOrWouldNotClose) {
  const TriMesh unit = box(Vec3(0.0), Vec3(1.0));
  const std::vector<std::vector<TriMesh>> cases = {
      // the shared square split along different diagonals: no face coincides
      {unit, box(Vec3(1.0, 0.0, 0.0), Vec3(2.0, 1.0, 1.0), true)},
      // along an edge only
      {unit, box(Vec3(1.0, 1.0, 0.0), Vec3(2.0, 2.0, 1.0))},
      // an open element, one triangle facing one of the box's: joined, the box would keep a hole
      {unit, lone_triangle(unit, 0)},
      // the same box twice: its faces coincide in the same orientation, never opposite
      {unit, unit},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    TriMesh layer = join_elements(cases[k]);
    const TriMesh before = layer;
    EXPECT_EQ(join_abutting_elements(layer, 1e-6), 0) << "case " << k;
    EXPECT_EQ(layer.positions, before.positions) << "case " << k;
    EXPECT_EQ(layer.elements, before.elements) << "case " << k;
  }
}

TEST(AbuttingElements, ThreeFacesOnTheSamePointsAreLeft) {
  // A box and two copies of its neighbour: three faces on each shared triangle, so no pair is
  // taken there, while a box pair elsewhere is joined.
  TriMesh layer = join_elements({box(Vec3(0.0), Vec3(1.0)), box(Vec3(1.0, 0.0, 0.0), Vec3(2.0, 1.0, 1.0)),
                                 box(Vec3(1.0, 0.0, 0.0), Vec3(2.0, 1.0, 1.0)),
                                 box(Vec3(10.0, 0.0, 0.0), Vec3(11.0, 1.0, 1.0)),
                                 box(Vec3(10.0, 1.0, 0.0), Vec3(11.0, 2.0, 1.0))});
  EXPECT_EQ(join_abutting_elements(layer, 1e-6), 1);
  EXPECT_EQ(element_count(layer), 4);
  const std::vector<TriMesh> parts = split_elements(layer);
  ASSERT_EQ(parts.size(), 4u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(parts[k].num_faces(), 12u) << k;
  EXPECT_NEAR(enclosed_volume(parts[3]), 2.0, 1e-12);
  EXPECT_TRUE(inspect_surface(parts[3]).closed_manifold());
}

}  // namespace
}  // namespace meshquilt
