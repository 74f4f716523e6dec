#include "mesh/base_mesh.h"

#include <gtest/gtest.h>

#include <optional>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

using test::canonical_cycle;
using test::signed_volume;

// The library is not asked: directed edge counts tell boundary and misoriented edges directly.
struct EdgeCounts {
  int64_t boundary = 0, misoriented = 0;
};
EdgeCounts count_edges(const TriMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  EdgeCounts c;
  for (const auto& [e, n] : directed) {
    const auto back = directed.find({e.second, e.first});
    const int reverse = back == directed.end() ? 0 : back->second;
    if (n == 1 && reverse == 0) ++c.boundary;
    if (n >= 2) ++c.misoriented;
  }
  return c;
}

// Flips each face with probability 1/2 (face 0 kept when keep_first).
TriMesh randomly_flipped(TriMesh m, uint32_t seed, bool keep_first = false) {
  std::mt19937 rng(seed);
  for (size_t f = keep_first ? 1 : 0; f < m.num_faces(); ++f)
    if (rng() & 1u) std::swap(m.triangles[f][1], m.triangles[f][2]);
  return m;
}

// The prepared faces, as oriented cycles, equal the reference's (no vertex renumbering expected for
// a mesh without duplicates).
void expect_same_oriented_faces(const TriMesh& prepared, const TriMesh& reference) {
  ASSERT_EQ(prepared.num_faces(), reference.num_faces());
  ASSERT_EQ(prepared.num_vertices(), reference.num_vertices());
  int wrong = 0;
  for (size_t f = 0; f < reference.num_faces(); ++f)
    if (canonical_cycle(prepared.triangles[f]) != canonical_cycle(reference.triangles[f])) ++wrong;
  EXPECT_EQ(wrong, 0);
}

std::string error_message(const std::function<void()>& body, std::optional<ErrorKind>* code = nullptr) {
  try {
    body();
  } catch (const InputError& e) {
    if (code) *code = e.kind();
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(PrepareBase, RandomlyFlippedSphereComesBackOutward) {
  const TriMesh sphere = test::icosphere(3);
  ASSERT_GT(signed_volume(sphere), 0.0);
  for (uint32_t seed : {1u, 2u, 3u}) {
    const TriMesh prepared = prepare_base(randomly_flipped(sphere, seed), "sphere");
    expect_same_oriented_faces(prepared, sphere);
    EXPECT_NEAR(signed_volume(prepared), signed_volume(sphere), 1e-12);
    const SurfaceReport report = inspect_surface(prepared);
    EXPECT_EQ(report.misoriented_edges, 0);
    EXPECT_EQ(report.boundary_edges, 0);
    EXPECT_EQ(count_edges(prepared).misoriented, 0);
  }
}

TEST(PrepareBase, InsideOutClosedMeshIsTurnedOutward) {
  TriMesh inverted = test::uv_sphere(12, 20, 2.0, Vec3(5.0, -3.0, 1.0));  // off the origin on purpose
  const TriMesh outward = inverted;
  for (Tri& t : inverted.triangles) std::swap(t[1], t[2]);
  ASSERT_LT(signed_volume(inverted), 0.0);
  const TriMesh prepared = prepare_base(inverted, "inverted");
  expect_same_oriented_faces(prepared, outward);
  EXPECT_GT(signed_volume(prepared), 0.0);
}

TEST(PrepareBase, OpenComponentFollowsItsFirstFace) {
  const TriMesh grid = test::flat_grid(6, 5, 1.0);
  const TriMesh prepared = prepare_base(randomly_flipped(grid, 7, /*keep_first=*/true), "grid");
  expect_same_oriented_faces(prepared, grid);
  // Flipping the first face too makes the whole (open) component follow it: every face reversed.
  TriMesh first_flipped = randomly_flipped(grid, 7, true);
  std::swap(first_flipped.triangles[0][1], first_flipped.triangles[0][2]);
  TriMesh reversed = grid;
  for (Tri& t : reversed.triangles) std::swap(t[1], t[2]);
  expect_same_oriented_faces(prepare_base(first_flipped, "grid"), reversed);
}

// Share of the area whose face normal looks away from `centre`, computed here from the faces.
double area_facing_away(const TriMesh& m, const Vec3& centre) {
  double away = 0.0, total = 0.0;
  for (const Tri& t : m.triangles) {
    const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const Vec3 n = glm::cross(b - a, c - a);
    const double area = glm::length(n);
    total += area;
    if (glm::dot(n, (a + b + c) / 3.0 - centre) > 0.0) away += area;
  }
  return away / total;
}

TEST(PrepareBase, OpenDomeIsTurnedToFaceOut) {
  // The upper half of a sphere, inside out and scrambled: an open component with an outside.
  const Vec3 centre(1.0, 2.0, -1.0);
  const TriMesh sphere = test::uv_sphere(12, 20, 1.5, centre);
  TriMesh dome;
  dome.positions = sphere.positions;
  for (const Tri& t : sphere.triangles) {
    const Vec3 c = (sphere.positions[t[0]] + sphere.positions[t[1]] + sphere.positions[t[2]]) / 3.0;
    if (c.z > centre.z + 0.3) dome.triangles.push_back({t[0], t[2], t[1]});
  }
  ASSERT_LT(area_facing_away(dome, centre), 0.01);
  for (uint32_t seed : {1u, 2u}) {
    const TriMesh prepared = prepare_base(randomly_flipped(dome, seed), "dome");
    EXPECT_GT(count_edges(prepared).boundary, 0);
    EXPECT_GT(area_facing_away(prepared, centre), 0.99);
  }
}

TEST(PrepareBase, EachComponentOrientedOnItsOwn) {
  // An outward sphere, an inside-out one and an open grid, all in one mesh, faces shuffled in flip.
  TriMesh a = test::uv_sphere(6, 10, 1.0, Vec3(-3.0, 0.0, 0.0));
  TriMesh b = test::icosphere(2, 1.5);
  for (Vec3& p : b.positions) p += Vec3(4.0, 1.0, 0.0);
  TriMesh c = test::flat_grid(3, 3, 0.5);
  for (Vec3& p : c.positions) p += Vec3(0.0, 6.0, 0.0);
  TriMesh joined, expected;
  for (const TriMesh* part : {&a, &b, &c}) {
    const int base = static_cast<int>(joined.num_vertices());
    joined.positions.insert(joined.positions.end(), part->positions.begin(), part->positions.end());
    for (Tri t : part->triangles) {
      for (int& v : t) v += base;
      expected.triangles.push_back(t);
      joined.triangles.push_back(t);
    }
  }
  expected.positions = joined.positions;
  // The inside-out sphere b: its faces in `joined` are reversed, the expectation stays outward.
  const size_t b_begin = a.num_faces(), b_end = b_begin + b.num_faces();
  for (size_t f = b_begin; f < b_end; ++f) std::swap(joined.triangles[f][1], joined.triangles[f][2]);
  joined.elements.assign(joined.num_faces(), 3);
  const TriMesh prepared = prepare_base(joined, "three parts");
  expect_same_oriented_faces(prepared, expected);
  EXPECT_TRUE(prepared.elements.empty());
}

TEST(PrepareBase, TriangleSoupIsWelded) {
  const TriMesh grid = test::flat_grid(4, 3, 1.0, 0.2);
  TriMesh soup;
  for (const Tri& t : grid.triangles) {
    const int base = static_cast<int>(soup.num_vertices());
    for (int v : t) soup.positions.push_back(grid.positions[v] + Vec3(1e-9, -1e-9, 0.0));  // within tolerance
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const TriMesh prepared = prepare_base(soup, "soup");
  EXPECT_EQ(prepared.num_vertices(), grid.num_vertices());
  EXPECT_EQ(prepared.num_faces(), grid.num_faces());
  EXPECT_EQ(count_edges(prepared).boundary, 2 * (4 + 3));
  EXPECT_EQ(count_edges(prepared).misoriented, 0);
}

TEST(PrepareBase, MoebiusStripIsRefused) {
  // A strip of n quads whose ends are glued with a half twist.
  const int n = 12;
  TriMesh m;
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * M_PI * i / n;
    for (double s : {-0.3, 0.3}) {
      const double r = 1.0 + s * std::cos(u / 2.0);
      m.positions.push_back(Vec3(r * std::cos(u), r * std::sin(u), s * std::sin(u / 2.0)));
    }
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    int c = 2 * ((i + 1) % n), d = c + 1;
    if (i == n - 1) std::swap(c, d);  // the twist
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  }
  std::optional<ErrorKind> code;
  const std::string message = error_message([&] { prepare_base(m, "moebius.obj"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
  EXPECT_EQ(message.rfind("moebius.obj: ", 0), 0u) << message;
  EXPECT_NE(message.find("non-orientable"), std::string::npos) << message;
}

TEST(PrepareBase, ThreeFacesOnOneEdgeAreRefused) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, -1, 0), Vec3(0.5, 0, 1)};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  std::optional<ErrorKind> code;
  const std::string message = error_message([&] { prepare_base(m, "fins.off"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
  EXPECT_EQ(message.rfind("fins.off: ", 0), 0u) << message;
  EXPECT_NE(message.find("non-manifold"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(PrepareBase, NonManifoldOnlyAfterWeldingIsRefused) {
  // Three faces whose shared edge uses separate but coincident vertices.
  TriMesh m;
  m.positions = {Vec3(0, 0, 0),    Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0, 0, 0),  Vec3(1, 0, 0),
                 Vec3(0.5, -1, 0), Vec3(0, 0, 0), Vec3(1, 0, 0),   Vec3(0.5, 0, 1)};
  m.triangles = {{0, 1, 2}, {4, 3, 5}, {6, 7, 8}};
  std::optional<ErrorKind> code;
  error_message([&] { prepare_base(m, "welded.obj"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
}

TEST(PrepareBase, NanCoordinateAndNoFacesAreRefused) {
  TriMesh nan = test::flat_grid(2, 2, 1.0);
  nan.positions[4].y = std::numeric_limits<double>::quiet_NaN();
  std::optional<ErrorKind> code;
  std::string message = error_message([&] { prepare_base(nan, "nan.off"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
  EXPECT_EQ(message.rfind("nan.off: ", 0), 0u) << message;

  TriMesh empty;
  empty.positions = {Vec3(0.0), Vec3(1.0, 0.0, 0.0)};
  code = std::nullopt;
  message = error_message([&] { prepare_base(empty, "empty.off"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
  EXPECT_EQ(message.rfind("empty.off: ", 0), 0u) << message;

  // Every face collapses when welded: nothing is left.
  TriMesh collapsed;
  collapsed.positions = {Vec3(0.0), Vec3(0.0), Vec3(0.0, 1e-13, 0.0), Vec3(1.0, 1.0, 1.0)};
  collapsed.triangles = {{0, 1, 2}, {3, 3, 1}};
  code = std::nullopt;
  message = error_message([&] { prepare_base(collapsed, "dust.obj"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
  EXPECT_EQ(message.rfind("dust.obj: ", 0), 0u) << message;

  // Corners apart but on a line: no face has area.
  TriMesh sliver;
  sliver.positions = {Vec3(0.0), Vec3(1.0, 0.0, 0.0), Vec3(2.0, 0.0, 0.0), Vec3(3.0, 0.0, 0.0)};
  sliver.triangles = {{0, 1, 2}, {1, 3, 2}};
  code = std::nullopt;
  message = error_message([&] { prepare_base(sliver, "line.off"); }, &code);
  EXPECT_EQ(code, ErrorKind::invalid_mesh);
  EXPECT_EQ(message.rfind("line.off: ", 0), 0u) << message;
  EXPECT_NE(message.find("no face has area"), std::string::npos) << message;
}

// --- real meshes ---------------------------------------------------------------------------

TriMesh read_shared(const std::string& name) { return read_mesh(test::shared_meshes() / name); }

TEST(PrepareBaseShared, TeapotDuplicatesAreWelded) {
  if (test::shared_meshes().empty()) GTEST_SKIP() << "no ../shared/data/meshes";
  const TriMesh raw = read_shared("teapot.obj");
  MeshRepairs repairs;
  const TriMesh prepared = prepare_base(raw, "teapot.obj", &repairs);
  EXPECT_LT(prepared.num_vertices() + 100, raw.num_vertices());  // hundreds of duplicates
  EXPECT_EQ(repairs.welded_vertices + repairs.unused_vertices - repairs.split_vertices,
            static_cast<int64_t>(raw.num_vertices() - prepared.num_vertices()));
  const EdgeCounts before = count_edges(raw), after = count_edges(prepared);
  EXPECT_LT(after.boundary, before.boundary);
  EXPECT_EQ(after.misoriented, 0);
  EXPECT_EQ(inspect_surface(prepared).misoriented_edges, 0);
  // No two kept vertices coincide any more (brute force over a sort by x).
  std::vector<Vec3> p = prepared.positions;
  std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a.x < b.x; });
  int coincident = 0;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size() && p[j].x - p[i].x <= 0.0; ++j)
      if (p[i] == p[j]) ++coincident;
  EXPECT_EQ(coincident, repairs.split_vertices);  // only the copies of pinched vertices
}

TEST(PrepareBaseShared, OpenHeadIsAccepted) {
  if (test::shared_meshes().empty()) GTEST_SKIP() << "no ../shared/data/meshes";
  const TriMesh raw = read_shared("head.off");
  const TriMesh prepared = prepare_base(randomly_flipped(raw, 11, true), "head.off");
  const EdgeCounts edges = count_edges(prepared);
  EXPECT_GT(edges.boundary, 0);
  EXPECT_EQ(edges.misoriented, 0);
  EXPECT_EQ(prepared.num_faces(), raw.num_faces());
  // The scan is open at the neck: its faces must still look out of the head, whichever way the
  // file ran them (the texture grows on the side the normals point to).
  Vec3 centre(0.0);
  for (const Vec3& p : raw.positions) centre += p;
  centre /= static_cast<double>(raw.num_vertices());
  EXPECT_GT(area_facing_away(prepared, centre), 0.8);
  TriMesh reversed = raw;
  for (Tri& t : reversed.triangles) std::swap(t[1], t[2]);
  EXPECT_GT(area_facing_away(prepare_base(reversed, "head.off"), centre), 0.8);
}

TEST(PrepareBaseShared, TwoComponentsOfTheKnotAreBothOutward) {
  if (test::shared_meshes().empty()) GTEST_SKIP() << "no ../shared/data/meshes";
  TriMesh raw = read_shared("knot2.off");
  // Turn the second component inside out and scramble the rest.
  const std::vector<int> raw_components = test::face_component_ids(raw);
  for (size_t f = 0; f < raw.num_faces(); ++f)
    if (raw_components[f] == 1) std::swap(raw.triangles[f][1], raw.triangles[f][2]);
  const TriMesh prepared = prepare_base(randomly_flipped(raw, 5), "knot2.off");
  const std::vector<int> component = test::face_component_ids(prepared);
  const int count = *std::max_element(component.begin(), component.end()) + 1;
  EXPECT_EQ(count, 2);
  EXPECT_EQ(count_edges(prepared).misoriented, 0);
  EXPECT_EQ(count_edges(prepared).boundary, 0);
  for (int c = 0; c < count; ++c) {
    TriMesh part;
    part.positions = prepared.positions;
    for (size_t f = 0; f < prepared.num_faces(); ++f)
      if (component[f] == c) part.triangles.push_back(prepared.triangles[f]);
    EXPECT_GT(signed_volume(part), 0.0) << "component " << c;
  }
}

TEST(PrepareBaseShared, GenusFourFertilityIsAcceptedOutward) {
  if (test::shared_meshes().empty()) GTEST_SKIP() << "no ../shared/data/meshes";
  TriMesh raw = read_shared("fertility.off");
  for (Tri& t : raw.triangles) std::swap(t[1], t[2]);
  const TriMesh prepared = prepare_base(randomly_flipped(raw, 3), "fertility.off");
  const SurfaceReport report = inspect_surface(prepared);
  EXPECT_EQ(report.misoriented_edges, 0);
  EXPECT_EQ(report.boundary_edges, 0);
  EXPECT_EQ(report.euler, 2 - 2 * 4);
  EXPECT_GT(signed_volume(prepared), 0.0);
}

TEST(PrepareBase, LaterFramesArePosedByRawVertexWithoutWeldingAgain) {
  // Two triangles sharing an edge, with the shared corners duplicated in the file (as an OBJ
  // exported per face gives them): 6 raw vertices, 4 after welding.
  TriMesh raw;
  raw.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  raw.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriMesh prepared = prepare_base(raw, "two.obj");
  const std::vector<int32_t> sources = prepared_vertex_sources(raw);
  ASSERT_EQ(sources.size(), prepared.num_vertices());
  for (size_t v = 0; v < sources.size(); ++v) EXPECT_EQ(prepared.positions[v], raw.positions[sources[v]]);
  // A later frame in which two vertices that were apart meet: posed, they stay two vertices.
  TriMesh frame = raw;
  for (Vec3& p : frame.positions) p += Vec3(0.0, 0.0, 2.0);
  frame.positions[4] = frame.positions[0];
  const TriMesh posed = posed_base(prepared, sources, frame);
  EXPECT_EQ(posed.triangles, prepared.triangles);
  ASSERT_EQ(posed.num_vertices(), prepared.num_vertices());
  for (size_t v = 0; v < sources.size(); ++v) EXPECT_EQ(posed.positions[v], frame.positions[sources[v]]);
}

}  // namespace
}  // namespace meshquilt
