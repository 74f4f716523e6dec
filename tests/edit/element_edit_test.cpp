// Element edits on rows of boxes built here: each box one element, its source the column.
#include "edit/element_edit.h"

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "mesh/topology.h"
#include "support/boxes.h"

namespace meshquilt {
namespace {

// `n` unit boxes along x, 2 apart; element k's source is k % sources.
TriMesh boxes(int n, int sources = 3) {
  std::vector<TriMesh> parts;
  for (int k = 0; k < n; ++k) parts.push_back(test::box(Vec3(2.0 * k, 0, 0), Vec3(2.0 * k + 1, 1, 1)));
  TriMesh m = join_elements(parts);
  for (int32_t e : m.elements) m.sources.push_back(e % sources);
  return m;
}

ElementView view_of(const TriMesh& m) { return {m.elements, m.sources, m.positions, m.triangles}; }

std::set<int32_t> ids(const std::vector<int32_t>& v) { return {v.begin(), v.end()}; }

TEST(ElementEdit, AgingRemovesTheShareAskedAndLeavesTheRestExactlyAsTheyWere) {
  const TriMesh m = boxes(200);
  EditRequest request;
  request.age = 0.1;
  request.seed = 3;
  EditCounts counts;
  const std::vector<int32_t> removed = elements_to_remove(view_of(m), request, counts);
  EXPECT_EQ(removed.size(), 20u);
  EXPECT_EQ(counts.aged, 20);
  EXPECT_EQ(counts.kept, 180);
  const TriMesh out = keep_faces(m, faces_kept(m.elements, removed));
  ASSERT_EQ(out.num_faces(), 180u * 12u);
  // Every kept element: the same ids and the same corner positions, face by face, in order.
  size_t g = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    if (ids(removed).count(m.elements[f])) continue;
    ASSERT_EQ(out.elements[g], m.elements[f]);
    ASSERT_EQ(out.sources[g], m.sources[f]);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(out.positions[out.triangles[g][k]], m.positions[m.triangles[f][k]]);
    ++g;
  }
  // The same seed chooses the same elements; another seed others.
  EditCounts again;
  EXPECT_EQ(elements_to_remove(view_of(m), request, again), removed);
  request.seed = 4;
  EXPECT_NE(elements_to_remove(view_of(m), request, again), removed);
}

TEST(ElementEdit, RemovingBySourceLeavesOnlyTheOtherSources) {
  const TriMesh m = boxes(30);
  EditRequest request;
  request.remove_sources = {1};
  EditCounts counts;
  const TriMesh out = keep_faces(m, faces_kept(m.elements, elements_to_remove(view_of(m), request, counts)));
  EXPECT_EQ(ids(out.sources), (std::set<int32_t>{0, 2}));
  EXPECT_EQ(counts.by_source, 10);
  request = {};
  request.keep_sources = {2};
  const TriMesh only = keep_faces(m, faces_kept(m.elements, elements_to_remove(view_of(m), request, counts)));
  EXPECT_EQ(ids(only.sources), (std::set<int32_t>{2}));
  EXPECT_EQ(counts.by_keep_source, 20);
}

TEST(ElementEdit, IdsBoxesAndSpheresRemoveWhatTheyName) {
  const TriMesh m = boxes(10);
  EditRequest request;
  request.remove_elements = {0, 9};
  EditRegion box;  // holds the centres of boxes 2 and 3 (x = 4.5, 6.5)
  box.lo = Vec3(4.0, 0.0, 0.0);
  box.hi = Vec3(7.0, 1.0, 1.0);
  EditRegion sphere;  // the centre of box 5 (10.5, 0.5, 0.5)
  sphere.kind = EditRegion::Kind::sphere;
  sphere.centre = Vec3(10.5, 0.5, 0.5);
  sphere.radius = 0.1;
  request.remove_inside = {box, sphere};
  EditCounts counts;
  EXPECT_EQ(elements_to_remove(view_of(m), request, counts), (std::vector<int32_t>{0, 2, 3, 5, 9}));
  EXPECT_EQ(counts.by_id, 2);
  EXPECT_EQ(counts.inside, 3);
}

TEST(ElementEdit, BadRequestsAreRefused) {
  const TriMesh m = boxes(4);
  EditRequest request;
  EditCounts counts;
  request.age = 1.5;
  EXPECT_THROW(elements_to_remove(view_of(m), request, counts), InputError);
  request.age = 0.0;
  request.remove_inside.push_back(EditRegion{});
  ElementView no_positions = view_of(m);
  no_positions.positions.clear();
  EXPECT_THROW(elements_to_remove(no_positions, request, counts), InputError);
  EXPECT_THROW(parse_palette("ff00"), InputError);
  EXPECT_THROW(parse_palette("ff0000,,00ff00"), InputError);
}

TEST(ElementEdit, ColoursCycleThroughThePaletteBySource) {
  const TriMesh m = boxes(6);
  const auto palette = parse_palette("#ff0000,00ff00");
  const auto colors = vertex_colors(m, ColorBy::source, palette);
  ASSERT_EQ(colors.size(), m.num_vertices());
  for (size_t f = 0; f < m.num_faces(); ++f)
    for (int32_t v : m.triangles[f]) EXPECT_EQ(colors[v], palette[m.sources[f] % 2]);
  TriMesh no_sources = m;
  no_sources.sources.clear();
  EXPECT_THROW(vertex_colors(no_sources, ColorBy::source, palette), InputError);
}

}  // namespace
}  // namespace meshquilt
