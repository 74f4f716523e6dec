#include "mesh/mesh_repair.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

#include "core/error.h"
#include "mesh/topology.h"
#include "support/boxes.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

using test::signed_volume;

// Closed, coherently wound and outward: every directed edge once, its reverse once, volume > 0.
// Counted here from the faces, not asked of the library.
void expect_closed_outward(const TriMesh& m, const std::string& what) {
  std::map<std::pair<int32_t, int32_t>, int> directed;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, n] : directed) {
    EXPECT_EQ(n, 1) << what << ": edge " << edge.first << "-" << edge.second << " run " << n << " times";
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << what << ": open edge";
  }
  EXPECT_GT(signed_volume(m), 0.0) << what;
}

std::string refusal(const TriMesh& m, const std::string& source) {
  try {
    repair_mesh(m, source);
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_mesh);
    return e.what();
  }
  ADD_FAILURE() << source << ": not refused";
  return {};
}

TEST(MeshRepair, CleanMeshComesBackUnchanged) {
  const TriMesh sphere = test::icosphere(2);
  const RepairedMesh r = repair_mesh(sphere, "sphere");
  EXPECT_FALSE(r.repairs.any()) << r.repairs.describe();
  EXPECT_EQ(r.mesh.positions, sphere.positions);
  EXPECT_EQ(r.mesh.triangles, sphere.triangles);
  EXPECT_TRUE(r.mesh.origins.empty());
  EXPECT_EQ(r.repairs.describe(), "");
}

TEST(MeshRepair, TubeInwardCapsOutwardIsRewound) {
  // The exported wire of the issue: a closed tube whose side faces look in and whose caps look
  // out, so the edges where they meet are run twice the same way.
  TriMesh wire;
  const int sides = 8, rings = 5;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < sides; ++i) {
      const double a = 2.0 * M_PI * i / sides;
      wire.positions.push_back(Vec3(0.07 * std::cos(a), 0.07 * std::sin(a), 0.25 * j));
    }
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < sides; ++i) {  // wound to look in
      const int32_t a = j * sides + i, b = j * sides + (i + 1) % sides;
      wire.triangles.push_back({a, b + sides, b});
      wire.triangles.push_back({a, a + sides, b + sides});
    }
  const size_t side_faces = wire.num_faces();
  for (int end = 0; end < 2; ++end) {  // a fan cap at each end, wound to look out
    const double z = end ? 1.0 : 0.0;
    const int32_t centre = static_cast<int32_t>(wire.num_vertices());
    wire.positions.push_back(Vec3(0.0, 0.0, z));
    std::vector<int32_t> rim;
    for (int32_t v = 0; v < centre; ++v)
      if (std::abs(wire.positions[v].z - z) < 1e-12) rim.push_back(static_cast<int32_t>(v));
    ASSERT_EQ(rim.size(), 8u);
    for (int i = 0; i < 8; ++i) {
      const int32_t a = rim[i], b = rim[(i + 1) % 8];
      wire.triangles.push_back(end ? Tri{centre, a, b} : Tri{centre, b, a});
    }
  }
  const RepairedMesh r = repair_mesh(wire, "wire.obj");
  expect_closed_outward(r.mesh, "wire");
  EXPECT_EQ(r.repairs.rewound_faces, static_cast<int64_t>(side_faces));
  EXPECT_EQ(r.repairs.rewound_parts, 1);
  EXPECT_EQ(r.mesh.num_faces(), wire.num_faces());
  EXPECT_NE(r.repairs.describe("elements").find("rewound " + std::to_string(side_faces) + " faces in 1 elements"),
            std::string::npos);
}

TEST(MeshRepair, AllInwardAndRandomlyFlippedBoxesTurnOut) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 10; ++trial) {
    TriMesh boxes = test::box(Vec3(0.0), Vec3(1.0, 2.0, 0.5));
    const TriMesh second = test::box(Vec3(3.0, 0.0, 0.0), Vec3(4.0, 1.0, 1.0));
    for (const Tri& t : second.triangles) boxes.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    boxes.positions.insert(boxes.positions.end(), second.positions.begin(), second.positions.end());
    int64_t flipped = 0;
    for (size_t f = 0; f < boxes.num_faces(); ++f)
      if (f < 12 || rng() % 2) {  // the first box all inward, the second at random
        std::swap(boxes.triangles[f][1], boxes.triangles[f][2]);
        ++flipped;
      }
    const RepairedMesh r = repair_mesh(boxes, "boxes.stl");
    expect_closed_outward(r.mesh, "boxes");
    EXPECT_EQ(r.repairs.rewound_faces, flipped);
  }
}

TEST(MeshRepair, SoupIsWeldedAndDuplicatesDropped) {
  const TriMesh sphere = test::icosphere(1);
  TriMesh soup;
  for (const Tri& t : sphere.triangles) {
    const int32_t base = static_cast<int32_t>(soup.num_vertices());
    for (int32_t v : t) soup.positions.push_back(sphere.positions[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  soup.triangles.push_back(soup.triangles[3]);                                  // the same face again
  soup.triangles.push_back({soup.triangles[7][1], soup.triangles[7][0], soup.triangles[7][2]});  // and reversed
  soup.positions.push_back(Vec3(1e6));  // a stray vertex no face uses
  const RepairedMesh r = repair_mesh(soup, "soup.stl");
  expect_closed_outward(r.mesh, "soup");
  EXPECT_EQ(r.mesh.num_vertices(), sphere.num_vertices());
  EXPECT_EQ(r.mesh.num_faces(), sphere.num_faces());
  EXPECT_EQ(r.repairs.duplicate_faces, 2);
  EXPECT_EQ(r.repairs.unused_vertices, 1);
  EXPECT_EQ(r.repairs.welded_vertices, static_cast<int64_t>(3 * sphere.num_faces() - sphere.num_vertices()));
  // Each kept vertex names a file vertex at its position.
  ASSERT_EQ(r.mesh.origins.size(), r.mesh.num_vertices());
  for (size_t v = 0; v < r.mesh.num_vertices(); ++v)
    EXPECT_EQ(r.mesh.positions[v], soup.positions[r.mesh.origins[v]]);
}

TEST(MeshRepair, TJunctionsAndZeroAreaFacesAreClosed) {
  // A box whose top face has an extra vertex at the middle of one edge; the side face below it
  // does not use it (a T-junction), or uses it through a zero-area face.
  const TriMesh box = test::box(Vec3(0.0), Vec3(1.0));
  for (bool with_sliver : {false, true}) {
    TriMesh m = box;
    // Top quad {4, 5, 7, 6}; the edge 4 -> 5 runs along y = 0, z = 1. Its side neighbour is the
    // y = 0 quad {0, 1, 5, 4}, triangles {0, 1, 5} and {0, 5, 4}.
    const int32_t mid = static_cast<int32_t>(m.num_vertices());
    m.positions.push_back(Vec3(0.5, 0.0, 1.0));
    m.triangles.pop_back();
    m.triangles.pop_back();
    m.triangles.push_back({4, mid, 6});
    m.triangles.push_back({mid, 5, 7});
    m.triangles.push_back({mid, 7, 6});
    if (with_sliver) m.triangles.push_back({4, 5, mid});  // along the line 4 - mid - 5
    const RepairedMesh r = repair_mesh(m, with_sliver ? "sliver.obj" : "tee.obj");
    expect_closed_outward(r.mesh, with_sliver ? "sliver" : "tee");
    EXPECT_EQ(r.repairs.t_junctions, 1);
    EXPECT_EQ(r.repairs.zero_area_faces, with_sliver ? 1 : 0);
    EXPECT_NEAR(signed_volume(r.mesh), 1.0, 1e-12);
  }
}

TEST(MeshRepair, PinchedVertexIsSplit) {
  // Two boxes meeting at one corner: the corner vertex carries two fans.
  TriMesh m = test::box(Vec3(0.0), Vec3(1.0));
  const TriMesh other = test::box(Vec3(1.0), Vec3(2.0));
  for (const Tri& t : other.triangles) {
    Tri u;
    for (int k = 0; k < 3; ++k) u[k] = t[k] == 0 ? 7 : t[k] + 8;  // its corner 0 is our corner 7
    m.triangles.push_back(u);
  }
  m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
  const RepairedMesh r = repair_mesh(m, "pinch.off");
  EXPECT_EQ(r.repairs.split_vertices, 1);
  expect_closed_outward(r.mesh, "pinch");
  int32_t parts = 0;
  face_components(r.mesh, &parts);
  EXPECT_EQ(parts, 2);
}

TEST(MeshRepair, ElementsAndColoursFollowTheFaces) {
  TriMesh m = test::box(Vec3(0.0), Vec3(1.0));
  m.elements.assign(m.num_faces(), 4);
  m.sources.assign(m.num_faces(), 2);
  for (size_t v = 0; v < m.num_vertices(); ++v) m.colors.push_back({uint8_t(v), 0, 0});
  for (Tri& t : m.triangles) std::swap(t[1], t[2]);
  m.triangles.push_back(m.triangles[0]);
  m.elements.push_back(4);
  m.sources.push_back(2);
  const RepairedMesh r = repair_mesh(m, "box.ply");
  ASSERT_EQ(r.mesh.elements.size(), r.mesh.num_faces());
  ASSERT_EQ(r.mesh.sources.size(), r.mesh.num_faces());
  ASSERT_EQ(r.mesh.colors.size(), r.mesh.num_vertices());
  for (size_t v = 0; v < r.mesh.num_vertices(); ++v) EXPECT_EQ(r.mesh.colors[v][0], r.mesh.origins[v]);
  expect_closed_outward(r.mesh, "box");
}

TEST(MeshRepair, WhatCannotBeRepairedIsRefusedWhereItIs) {
  // Three faces on the edge 0 - 1, after two clean faces: the file's face numbers are named.
  TriMesh fins;
  fins.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, -1, 0), Vec3(0.5, 0, 1),
                    Vec3(5, 5, 5), Vec3(6, 5, 5), Vec3(5, 6, 5)};
  fins.triangles = {{5, 6, 7}, {5, 7, 6}, {0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const std::string message = refusal(fins, "fins.off");
  EXPECT_EQ(message.rfind("fins.off: non-manifold edge shared by 3 faces (faces 2, 3, 4)", 0), 0u) << message;

  // A Moebius strip has no coherent winding.
  TriMesh strip;
  const int n = 12;
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * M_PI * i / n;
    for (double s : {-0.3, 0.3}) {
      const double r = 1.0 + s * std::cos(u / 2.0);
      strip.positions.push_back(Vec3(r * std::cos(u), r * std::sin(u), s * std::sin(u / 2.0)));
    }
  }
  for (int i = 0; i < n; ++i) {
    int c = 2 * ((i + 1) % n), d = c + 1;
    if (i == n - 1) std::swap(c, d);
    strip.triangles.push_back({2 * i, c, d});
    strip.triangles.push_back({2 * i, d, 2 * i + 1});
  }
  EXPECT_NE(refusal(strip, "strip.obj").find("strip.obj: non-orientable part (a Moebius-like strip around face "),
            std::string::npos);
}

TEST(MeshRepair, RepairIsIdempotent) {
  std::mt19937 rng(9);
  TriMesh m = test::uv_sphere(8, 12);
  for (Tri& t : m.triangles)
    if (rng() % 3 == 0) std::swap(t[1], t[2]);
  const RepairedMesh once = repair_mesh(m, "once");
  const RepairedMesh twice = repair_mesh(once.mesh, "twice");
  EXPECT_TRUE(once.repairs.any());
  EXPECT_EQ(twice.mesh.triangles, once.mesh.triangles);
  EXPECT_EQ(twice.mesh.positions, once.mesh.positions);
}

}  // namespace
}  // namespace meshquilt
