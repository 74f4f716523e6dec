// Elements into space: through the final map, except those that would meet another, which go
// through the map synthesis decided on.
#include "surface/element_placement.h"

#include <gtest/gtest.h>

#include "spatial/intersecting_pairs.h"

namespace meshquilt {
namespace {

// Local coordinates read as a plane: x, y from the barycentrics, z the height. The final map
// slides everything between x = 0.2 and x = 3 left by 1.5; the synthesis map is the identity.
class SlidingEmbedding final : public SurfaceEmbedding {
 public:
  explicit SlidingEmbedding(bool distinct) : distinct_(distinct) {}
  Vec3 position(const SurfacePoint& p, double height) const override {
    const double x = p.bary.x;
    return {x > 0.2 && x < 3.0 ? x - 1.5 : x, p.bary.y, height};
  }
  Vec3 position_during_synthesis(const SurfacePoint& p, double height) const override {
    return distinct_ ? Vec3(p.bary.x, p.bary.y, height) : position(p, height);
  }
  bool has_synthesis_map() const override { return distinct_; }

 private:
  bool distinct_;
};

struct Elements {
  std::vector<LocalVertex> vertices;
  std::vector<Tri> triangles;
  std::vector<int32_t> face_element;
  int32_t count = 0;

  // A tetrahedron one unit across in x, starting at x0.
  void add_tetrahedron(double x0) {
    const auto first = static_cast<int32_t>(vertices.size());
    for (const Vec3& c : {Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.3, 1.0, 0.0), Vec3(0.4, 0.3, 0.8)})
      vertices.push_back({SurfacePoint{0, {x0 + c.x, c.y}}, c.z});
    for (const Tri& t : {Tri{0, 2, 1}, Tri{0, 1, 3}, Tri{1, 2, 3}, Tri{2, 0, 3}}) {
      triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
      face_element.push_back(count);
    }
    ++count;
  }
  size_t pairs(const std::vector<Vec3>& positions) const {
    TriMesh mesh;
    mesh.positions = positions;
    mesh.triangles = triangles;
    return intersecting_face_pairs(mesh, face_element, IntersectionScope::different_elements).size();
  }
};

Elements three_tetrahedra() {
  Elements e;
  e.add_tetrahedron(-1.5);  // left of the slide: both maps agree
  e.add_tetrahedron(0.5);   // slides onto the first under the final map
  e.add_tetrahedron(4.0);   // right of the slide, alone either way
  return e;
}

TEST(PlaceElements, ElementsThatWouldMeetGoThroughTheSynthesisMap) {
  const Elements e = three_tetrahedra();
  const SlidingEmbedding embedding(true);
  std::vector<Vec3> final_positions;
  for (const LocalVertex& v : e.vertices) final_positions.push_back(embedding.position(v.point, v.height));
  ASSERT_GT(e.pairs(final_positions), 0u);  // the final map alone makes them meet

  const ElementPlacement placed = place_elements(embedding, e.vertices, e.triangles, e.face_element);
  EXPECT_EQ(placed.moved_elements(), 2);
  EXPECT_EQ(placed.through_synthesis_map, (std::vector<uint8_t>{1, 1, 0}));
  EXPECT_EQ(e.pairs(placed.positions), 0u);
  for (size_t v = 0; v < e.vertices.size(); ++v) {
    const LocalVertex& l = e.vertices[v];
    const Vec3 expected = v < 8 ? embedding.position_during_synthesis(l.point, l.height)
                                : embedding.position(l.point, l.height);
    EXPECT_EQ(placed.positions[v], expected) << v;
  }
  // The same inputs give the same positions.
  EXPECT_EQ(place_elements(embedding, e.vertices, e.triangles, e.face_element).positions,
            placed.positions);
}

TEST(PlaceElements, AnEmbeddingWithoutASynthesisMapPlacesEverythingThroughItsMap) {
  const Elements e = three_tetrahedra();
  const SlidingEmbedding embedding(false);
  const ElementPlacement placed = place_elements(embedding, e.vertices, e.triangles, e.face_element);
  EXPECT_EQ(placed.moved_elements(), 0);
  for (size_t v = 0; v < e.vertices.size(); ++v)
    EXPECT_EQ(placed.positions[v], embedding.position(e.vertices[v].point, e.vertices[v].height));
  EXPECT_GT(e.pairs(placed.positions), 0u);  // nothing to fall back on: the clean-up's business
}

}  // namespace
}  // namespace meshquilt
