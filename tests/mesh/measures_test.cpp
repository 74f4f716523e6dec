// Mean edge length and area-weighted vertex normals against closed-form answers.

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "mesh/measures.h"
#include "support/bumpy_sphere.h"

namespace meshquilt {
namespace {

TEST(MeanEdgeLength, RightTriangleCountsEachFaceEdge) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {3, 0, 0}, {0, 4, 0}};
  m.triangles = {{0, 1, 2}};
  EXPECT_DOUBLE_EQ(mean_edge_length(m), (3.0 + 4.0 + 5.0) / 3.0);
  // A shared edge counts once per face: two unit right triangles forming a square.
  TriMesh square;
  square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_DOUBLE_EQ(mean_edge_length(square), (4.0 + 2.0 * std::sqrt(2.0)) / 6.0);
}

TEST(MeanEdgeLength, ZeroWithoutFaces) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(mean_edge_length(m), 0.0);
}

// A right triangle: the centroid, and the farthest corner's distance from it (closed form).
TEST(FaceSpheres, CentroidAndFarthestCorner) {
  TriMesh mesh;
  mesh.positions = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}, {3, 3, 3}};
  const std::vector<FaceSphere> spheres = face_spheres(mesh);
  ASSERT_EQ(spheres.size(), 2u);
  EXPECT_EQ(spheres[0].centre, Vec3(1, 1, 0));
  EXPECT_NEAR(spheres[0].radius, std::sqrt(5.0), 1e-11);
  EXPECT_GE(spheres[0].radius, std::sqrt(5.0));  // padded, never short
  EXPECT_EQ(spheres[1].centre, Vec3(5, 5, 5));
  EXPECT_EQ(spheres[1].radius, 0.0);
}

TEST(VertexNormals, AreaWeightedAcrossAFold) {
  // Two faces meeting at edge 0-1: one in the x-y plane (area 0.5, normal +z), one in the x-z
  // plane with twice the area (normal -y), so the shared vertices get (0,-2,1)/sqrt(5).
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  const std::vector<Vec3> n = vertex_normals(m);
  ASSERT_EQ(n.size(), 4u);
  const Vec3 shared = Vec3(0, -2, 1) / std::sqrt(5.0);
  for (int v : {0, 1}) EXPECT_LT(glm::length(n[v] - shared), 1e-15) << v;
  EXPECT_LT(glm::length(n[2] - Vec3(0, 0, 1)), 1e-15);
  EXPECT_LT(glm::length(n[3] - Vec3(0, -1, 0)), 1e-15);
}

TEST(VertexNormals, FallbackForVerticesWithoutArea) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
  m.triangles = {{0, 1, 2}};  // collinear: no area; vertex 3 has no face
  for (const Vec3& n : vertex_normals(m)) EXPECT_EQ(n, Vec3(0, 0, 1));
  for (const Vec3& n : vertex_normals(m, Vec3(0.0))) EXPECT_EQ(n, Vec3(0.0));
}

TEST(VertexNormals, SphereNormalsPointOutward) {
  const TriMesh m = test::bumpy_sphere(8, 12, 1.0, Vec3(0.5, -1, 2), 3, 0.02);
  const std::vector<Vec3> n = vertex_normals(m);
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    EXPECT_NEAR(glm::length(n[v]), 1.0, 1e-12);
    EXPECT_GT(glm::dot(n[v], glm::normalize(m.positions[v] - Vec3(0.5, -1, 2))), 0.9) << v;
  }
}

}  // namespace
}  // namespace meshquilt
