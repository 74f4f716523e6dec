#include "surface/surface_cells.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>
#include <set>
#include <vector>

#include "mesh/mesh_io.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

double longest_edge(const TriMesh& m, size_t f) {
  const Tri& t = m.triangles[f];
  double longest = 0.0;
  for (int k = 0; k < 3; ++k)
    longest = std::max(longest, glm::distance(m.positions[t[k]], m.positions[t[(k + 1) % 3]]));
  return longest;
}

// Lattice size of each face from its cell count (m^2 cells), asserting it is a square.
int lattice_size(const SurfaceCells& cells, size_t f) {
  const int count = cells.face_offsets[f + 1] - cells.face_offsets[f];
  const int m = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
  EXPECT_EQ(m * m, count) << "face " << f;
  return m;
}

// Every property the header promises, against brute force.
void check_cells(const TriMesh& mesh, double cell_size) {
  const BaseSurface base(mesh);
  const SurfaceCells cells = make_surface_cells(base, cell_size);
  const size_t count = cells.centres.size();
  ASSERT_EQ(cells.areas.size(), count);
  ASSERT_EQ(cells.neighbours.size(), count);
  ASSERT_EQ(cells.face_offsets.size(), mesh.num_faces() + 1);
  EXPECT_EQ(cells.face_offsets.front(), 0);
  EXPECT_EQ(cells.face_offsets.back(), static_cast<int32_t>(count));

  double total = 0.0, area = 0.0;
  for (double a : cells.areas) total += a;
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    area += test::triangle_area(mesh.positions[mesh.triangles[f][0]], mesh.positions[mesh.triangles[f][1]],
                                mesh.positions[mesh.triangles[f][2]]);
  EXPECT_NEAR(total / area, 1.0, 1e-12);

  std::vector<double> size(count);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const int m = lattice_size(cells, f);
    const double longest = longest_edge(mesh, f);
    // No cell wider than the cell size, and no finer split than needed for that.
    EXPECT_LE(longest / m, cell_size * (1.0 + 1e-12)) << "face " << f;
    if (m > 1) {
      EXPECT_GT(longest / (m - 1), cell_size) << "face " << f;
    }
    // The centres are exactly the centroids of the m x m lattice sub-triangles, enumerated here
    // from their corners (scaled by 3m to stay in integers).
    std::multiset<std::pair<int, int>> expected, got;
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j) {
        expected.insert({3 * i + 1, 3 * j + 1});                     // (i,j) (i+1,j) (i,j+1)
        if (i + j + 1 < m) expected.insert({3 * i + 2, 3 * j + 2});  // (i+1,j) (i,j+1) (i+1,j+1)
      }
    for (int32_t c = cells.face_offsets[f]; c < cells.face_offsets[f + 1]; ++c) {
      EXPECT_EQ(cells.centres[c].face, static_cast<int32_t>(f));
      got.insert({static_cast<int>(std::lround(cells.centres[c].bary.x * 3 * m)),
                  static_cast<int>(std::lround(cells.centres[c].bary.y * 3 * m))});
      EXPECT_NEAR(cells.areas[c], base.face_areas[f] / (m * m), 1e-15 * area);
      size[c] = longest / m;
    }
    EXPECT_EQ(got, expected) << "face " << f;
  }

  // Neighbours: symmetric, no self loops or duplicates, and exactly the pairs closer than 1.5 x the
  // larger size (brute force over all pairs).
  std::vector<Vec3> p(count);
  for (size_t c = 0; c < count; ++c) p[c] = base.position(cells.centres[c]);
  for (size_t c = 0; c < count; ++c) {
    const std::set<int32_t> listed(cells.neighbours[c].begin(), cells.neighbours[c].end());
    EXPECT_EQ(listed.size(), cells.neighbours[c].size()) << "duplicates at " << c;
    EXPECT_FALSE(listed.count(static_cast<int32_t>(c))) << "self loop at " << c;
    std::set<int32_t> expected;
    for (size_t d = 0; d < count; ++d)
      if (d != c && glm::distance(p[c], p[d]) < 1.5 * std::max(size[c], size[d]))
        expected.insert(static_cast<int32_t>(d));
    EXPECT_EQ(listed, expected) << "cell " << c;
    for (int32_t d : listed) {
      const auto& back = cells.neighbours[d];
      EXPECT_TRUE(std::find(back.begin(), back.end(), static_cast<int32_t>(c)) != back.end())
          << c << " " << d;
    }
  }
}

TEST(SurfaceCells, SmallTrianglesStayWhole) {
  const TriMesh grid = test::flat_grid(4, 3, 0.5, 0.2);
  check_cells(grid, 1.0);
  const SurfaceCells cells = make_surface_cells(BaseSurface(grid), 1.0);
  EXPECT_EQ(cells.centres.size(), grid.num_faces());
  for (size_t f = 0; f < grid.num_faces(); ++f) EXPECT_EQ(cells.centres[f].bary, glm::dvec2(1.0 / 3.0));
}

TEST(SurfaceCells, TriangleTenTimesTheCellSizeIsSplit) {
  TriMesh m;
  m.positions = {Vec3(0.0), Vec3(10.0, 0.0, 0.0), Vec3(3.0, 6.0, 1.0)};
  m.triangles = {{0, 1, 2}};
  check_cells(m, 1.0);
  const SurfaceCells cells = make_surface_cells(BaseSurface(m), 1.0);
  EXPECT_EQ(cells.centres.size(), 100u);  // longest edge 10 (exactly): m = 10
  // Edge-adjacent sub-triangles are always neighbours: the cells of one face form one connected
  // graph.
  std::vector<char> seen(cells.centres.size(), 0);
  std::queue<int32_t> queue;
  queue.push(0);
  seen[0] = 1;
  int reached = 0;
  while (!queue.empty()) {
    const int32_t c = queue.front();
    queue.pop();
    ++reached;
    for (int32_t d : cells.neighbours[c])
      if (!seen[d]) seen[d] = 1, queue.push(d);
  }
  EXPECT_EQ(reached, 100);
}

TEST(SurfaceCells, MixedSizesOnACurvedSurface) {
  // Triangles of very different sizes (a cone's apex fan and its wide outer rings) and a cell size
  // between them: neighbour reach then differs per pair.
  check_cells(test::cone(0.6, 2.0, 4, 12), 0.3);
  check_cells(test::uv_sphere(5, 8, 1.5), 0.4);
}

TEST(SurfaceCells, SharedBunnyCoversItsArea) {
  const auto dir = test::shared_meshes();
  if (dir.empty()) GTEST_SKIP() << "no ../shared/data/meshes";
  const TriMesh bunny = read_mesh(dir / "bunny.off");
  const BaseSurface base(bunny);
  // A cell size below the longest edges so that some faces split.
  double longest = 0.0;
  for (size_t f = 0; f < bunny.num_faces(); ++f) longest = std::max(longest, longest_edge(bunny, f));
  const double cell_size = 0.4 * longest;
  const SurfaceCells cells = make_surface_cells(base, cell_size);
  EXPECT_GT(cells.centres.size(), bunny.num_faces());
  double total = 0.0;
  for (double a : cells.areas) total += a;
  EXPECT_NEAR(total / base.area, 1.0, 1e-12);
  for (size_t f = 0; f < bunny.num_faces(); ++f) {
    const int m = lattice_size(cells, f);
    EXPECT_LE(longest_edge(bunny, f) / m, cell_size * (1.0 + 1e-12));
  }
  size_t links = 0;
  for (size_t c = 0; c < cells.centres.size(); ++c) {
    for (int32_t d : cells.neighbours[c]) {
      EXPECT_NE(d, static_cast<int32_t>(c));
      const auto& back = cells.neighbours[d];
      EXPECT_TRUE(std::find(back.begin(), back.end(), static_cast<int32_t>(c)) != back.end());
    }
    links += cells.neighbours[c].size();
  }
  EXPECT_GT(links, cells.centres.size());
}

}  // namespace
}  // namespace meshquilt
