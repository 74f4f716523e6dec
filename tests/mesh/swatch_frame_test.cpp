// Swatch frame (Section 2.1): thinnest axis to +z by a proper rotation, bbox minimum at the origin.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <string>

#include "core/error.h"
#include "mesh/swatch_frame.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

// A closed box [origin, origin + size] with outward faces and two elements: the box and a
// smaller box inside it, so element ids must be carried along.
TriMesh box(const Vec3& origin, const Vec3& size) {
  const Tri faces[12] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                         {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  TriMesh m;
  for (int part = 0; part < 2; ++part) {
    const Vec3 o = part == 0 ? origin : origin + size * 0.25;
    const Vec3 s = part == 0 ? size : size * 0.5;
    const auto base = static_cast<int32_t>(m.positions.size());
    for (int k = 0; k < 8; ++k) {
      const Vec3 corner((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0, (k == 2 || k == 3 || k == 6 || k == 7) ? 1 : 0,
                        k >= 4 ? 1 : 0);
      m.positions.push_back(o + corner * s);
    }
    for (const Tri& f : faces) {
      m.triangles.push_back({f[0] + base, f[1] + base, f[2] + base});
      m.elements.push_back(part);
    }
  }
  return m;
}

double signed_volume(const TriMesh& m, int element) {
  double volume = 0.0;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.elements[f] != element) continue;
    const Tri& t = m.triangles[f];
    volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  }
  return volume;
}

struct Extents {
  Vec3 low, high;
};
Extents extents(const TriMesh& m) {
  Extents e{m.positions[0], m.positions[0]};
  for (const Vec3& p : m.positions) {
    e.low = glm::min(e.low, p);
    e.high = glm::max(e.high, p);
  }
  return e;
}

// Maps each thin axis to the expected rotated position (a cyclic permutation, written out here).
Vec3 expected_position(const Vec3& p, const Vec3& low, int thin) {
  const Vec3 q = p - low;
  if (thin == 0) return {q.y, q.z, q.x};
  if (thin == 1) return {q.z, q.x, q.y};
  return q;
}

TEST(SwatchFrame, ThinAxisBecomesZWithOrientationKept) {
  const Vec3 origin(5, -1, 7);
  const Vec3 sizes[3] = {{0.1, 2, 3}, {2, 0.1, 3}, {2, 3, 0.1}};
  for (int thin = 0; thin < 3; ++thin) {
    const TriMesh swatch = box(origin, sizes[thin]);
    const double outer = signed_volume(swatch, 0);
    ASSERT_GT(outer, 0.0);
    const TriMesh framed = orient_swatch(swatch, "swatch.obj");
    EXPECT_EQ(framed.triangles, swatch.triangles);
    EXPECT_EQ(framed.elements, swatch.elements);
    const Extents e = extents(framed);
    EXPECT_EQ(e.low, Vec3(0.0));
    EXPECT_NEAR(e.high.z, 0.1, 1e-12) << "thin axis " << thin;
    EXPECT_GT(e.high.x, 1.9);
    EXPECT_GT(e.high.y, 1.9);
    for (size_t v = 0; v < swatch.positions.size(); ++v) {
      const Vec3 expected = expected_position(swatch.positions[v], origin, thin);
      EXPECT_NEAR(glm::length(framed.positions[v] - expected), 0.0, 1e-12) << "thin axis " << thin << " vertex " << v;
    }
    // A proper rotation keeps every enclosed volume and its sign.
    EXPECT_NEAR(signed_volume(framed, 0), outer, 1e-12);
    EXPECT_NEAR(signed_volume(framed, 1), signed_volume(swatch, 1), 1e-12);
    EXPECT_EQ(thinnest_axis(sizes[thin]), thin);
  }
}

TEST(SwatchFrame, TiesKeepZ) {
  EXPECT_EQ(thinnest_axis({1, 1, 1}), 2);
  EXPECT_EQ(thinnest_axis({1, 2, 1}), 2);
  EXPECT_EQ(thinnest_axis({1, 1, 2}), 0);
}

TEST(SwatchFrame, DegenerateSwatchesThrow) {
  auto expect_degenerate = [](const TriMesh& m, const std::string& what) {
    try {
      orient_swatch(m, "chain.obj");
      ADD_FAILURE() << what << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_mesh) << what;
      // A line or a point has no face with area left after repair: said as such.
      const std::string message = e.what();
      EXPECT_TRUE(message.rfind("chain.obj: degenerate swatch: ", 0) == 0 ||
                  message.rfind("chain.obj: no face has area", 0) == 0)
          << message;
    }
  };
  TriMesh flat;
  flat.positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  flat.triangles = {{0, 1, 2}, {1, 3, 2}};
  expect_degenerate(flat, "flat in z");
  TriMesh almost = flat;
  almost.positions[3].z += 1e-12;  // below 1e-9 x diagonal
  expect_degenerate(almost, "nearly flat");
  TriMesh line;
  line.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  line.triangles = {{0, 1, 2}};
  expect_degenerate(line, "a line");
  TriMesh point = line;
  point.positions = {{3, 3, 3}, {3, 3, 3}, {3, 3, 3}};
  expect_degenerate(point, "a point");
  // Just above the limit is accepted.
  TriMesh thin = flat;
  thin.positions[3].z += 1e-8;
  EXPECT_NO_THROW(orient_swatch(thin, "chain.obj"));
  // Invalid meshes are reported by validation, naming the source.
  EXPECT_THROW(orient_swatch(TriMesh{}, "chain.obj"), InputError);
}

}  // namespace
}  // namespace meshquilt
