// The patch step on its own (quilt/patch_step.h): which cells it reports covered, that a refused
// input leaves its cells for another try, and that an element longer than several patches takes
// part through a pinned part that can be put back exactly.
#include "quilt/patch_step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "device.h"
#include "mesh/topology.h"
#include "support/boxes.h"
#include "support/torus.h"
#include "swatch/tube_mesh.h"

namespace meshquilt {
namespace {

constexpr double kRadius = 0.1;
constexpr int kSides = 8;

// A straight capped tube along x at height kRadius, from x0 to x1 at y, one ring per 0.1.
void add_tube(TriMesh& mesh, double x0, double x1, double y, int32_t element) {
  std::vector<Vec3> centre, normal;
  const int rings = static_cast<int>(std::lround((x1 - x0) / 0.1));
  for (int k = 0; k <= rings; ++k) {
    centre.emplace_back(x0 + (x1 - x0) * k / rings, y, kRadius);
    normal.emplace_back(0.0, 1.0, 0.0);
  }
  append_tube(mesh, centre, normal, kRadius, kSides, TubeEnds::capped, element,
              std::vector<Vec3>(centre.size(), Vec3(1.0, 0.0, 0.0)));
}

// Three parallel yarns 4 long, 1.5 apart: a swatch of three elements (in its frame the yarns'
// centrelines lie at y = 0.1, 1.6 and 3.1).
TriMesh three_yarns() {
  TriMesh swatch;
  add_tube(swatch, 0.0, 4.0, 0.5, 0);
  add_tube(swatch, 0.0, 4.0, 2.0, 1);
  add_tube(swatch, 0.0, 4.0, 3.5, 2);
  return swatch;
}

// A thin plate standing from y = 5 to 6.2 at x, 0.4 high: an element of no swatch.
PlaneElement plate_at(double x) {
  PlaneElement plate;
  const double a = x - 0.05, b = x + 0.05;
  plate.mesh.positions = {{a, 5.0, 0.0}, {b, 5.0, 0.0}, {b, 6.2, 0.0}, {a, 6.2, 0.0},
                          {a, 5.0, 0.4}, {b, 5.0, 0.4}, {b, 6.2, 0.4}, {a, 6.2, 0.4}};
  plate.mesh.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                          {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  plate.bounds = xy_bounds(plate.mesh);
  return plate;
}

struct StepFixture : ::testing::Test {
  void SetUp() override {
    swatch = prepare_swatch(three_yarns());
    device = engine::open_device(engine::BackendChoice::cpu);
    grid.cell = 0.25;
    grid.nx = grid.ny = 64;  // [0, 16]^2
    matcher = std::make_unique<GeometryMatcher>(*device, swatch.mesh, grid.cell);
    step.correspondence.lambda = 1.0 / swatch.mean_edge;
  }
  PatchRequest request_at(const glm::dvec2& t, const Rect2& domain) const {
    PatchRequest request;
    request.grid = grid;
    request.candidates = {t};
    request.sub_patch = {t + glm::dvec2(0.2), t + glm::dvec2(0.7)};  // clear of the layers below, so t stays
    request.inside_domain = [domain](const glm::dvec2& p) { return domain.contains(p); };
    return request;
  }
  PatchOutcome run(std::vector<PlaneElement>& layer, const PatchRequest& request) {
    std::mt19937_64 rng(1);
    return quilt_patch(layer, request, swatch, *matcher, step, rng, counts, seconds);
  }
  // The footprint-interior rule written out cell by cell: the centre and its four neighbours
  // (one cell away) lie in the footprint or outside the domain.
  std::vector<uint8_t> interior(const Rect2& footprint, const Rect2& domain) const {
    std::vector<uint8_t> cells(static_cast<size_t>(grid.nx) * grid.ny, 0);
    const auto settled = [&](double x, double y) {
      return (x >= footprint.lo.x && x <= footprint.hi.x && y >= footprint.lo.y && y <= footprint.hi.y) ||
             !(x >= domain.lo.x && x <= domain.hi.x && y >= domain.lo.y && y <= domain.hi.y);
    };
    for (int y = 0; y < grid.ny; ++y)
      for (int x = 0; x < grid.nx; ++x) {
        const double cx = (x + 0.5) * grid.cell, cy = (y + 0.5) * grid.cell;
        const bool inside = cx >= footprint.lo.x && cx <= footprint.hi.x && cy >= footprint.lo.y &&
                            cy <= footprint.hi.y && domain.contains(glm::dvec2(cx, cy));
        cells[static_cast<size_t>(y) * grid.nx + x] =
            inside && settled(cx + grid.cell, cy) && settled(cx - grid.cell, cy) &&
            settled(cx, cy + grid.cell) && settled(cx, cy - grid.cell);
      }
    return cells;
  }

  // The outcome's covered cells over the whole grid.
  std::vector<uint8_t> covered_grid(const PatchOutcome& outcome) const {
    std::vector<uint8_t> cells(static_cast<size_t>(grid.nx) * grid.ny, 0);
    for (int y = 0; y < grid.ny; ++y)
      for (int x = 0; x < grid.nx; ++x) cells[grid.index(x, y)] = outcome.covers_cell(x, y);
    return cells;
  }

  QuiltSwatch swatch;
  std::unique_ptr<engine::Device> device;
  std::unique_ptr<GeometryMatcher> matcher;
  PlaneGrid grid;
  PatchStepOptions step;
  MergeCounts counts;
  std::map<std::string, double> seconds;
};

TEST_F(StepFixture, FirstPatchCoversTheFootprintInterior) {
  const Rect2 domain{glm::dvec2(0.0), glm::dvec2(16.0)};
  std::vector<PlaneElement> layer;
  const PatchOutcome outcome = run(layer, request_at({4.0, 4.0}, domain));
  EXPECT_EQ(outcome.added.size(), 3u);
  EXPECT_EQ(layer.size(), 3u);
  EXPECT_EQ(outcome.footprint.lo, glm::dvec2(4.0, 4.0));
  // The swatch is its elements: kept geometry lies wherever the swatch has some, so the whole
  // interior is covered, and nothing else.
  EXPECT_EQ(covered_grid(outcome), interior(outcome.footprint, domain));
  EXPECT_GT(std::count(outcome.covered.begin(), outcome.covered.end(), 1), 0);
}

TEST_F(StepFixture, DomainEdgeCellsAreCoveredWhereTheFootprintMeetsIt) {
  const Rect2 domain{glm::dvec2(0.0), glm::dvec2(16.0)};
  std::vector<PlaneElement> layer;
  const PatchOutcome outcome = run(layer, request_at({0.0, 0.0}, domain));
  const std::vector<uint8_t> expected = interior(outcome.footprint, domain);
  EXPECT_EQ(covered_grid(outcome), expected);
  EXPECT_TRUE(outcome.covers_cell(0, 2)) << "column 0 touches the domain's edge";
  EXPECT_FALSE(outcome.covers_cell(grid.column(outcome.footprint.hi.x - 0.1), 2))
      << "the last column inside the domain is where the next seam goes";
}

TEST_F(StepFixture, RefusedInputLeavesItsCellsUncovered) {
  const Rect2 domain{glm::dvec2(0.0), glm::dvec2(16.0)};
  // A plate standing across where the middle yarn will go (x = 6, y = 5.6), clear of the others
  // (y = 4.1 and 7.1), unrelated to all.
  std::vector<PlaneElement> layer{plate_at(6.0)};
  const PatchOutcome outcome = run(layer, request_at({4.0, 4.0}, domain));
  EXPECT_EQ(counts.rejected_inputs, 1);
  EXPECT_EQ(outcome.added.size(), 2u);
  // Under the refused yarn, more than a cell from the plate: uncovered, to be seeded again.
  EXPECT_FALSE(outcome.covers(grid, {4.6, 5.6}));
  // Between yarns the swatch is empty: covered. Under the plate: kept geometry, covered.
  EXPECT_TRUE(outcome.covers(grid, {4.6, 4.85}));
  EXPECT_TRUE(outcome.covers(grid, {6.0, 5.6}));
}

// On a surface a patch places only elements that lie wholly in it; one crossing its edge is left
// for a later patch, so the cells under its part inside still need kept geometry: the swatch is
// not empty there.
TEST_F(StepFixture, ElementsLeftOutAtThePatchEdgeLeaveTheirCellsUncovered) {
  const Rect2 domain{glm::dvec2(0.0), glm::dvec2(6.0, 16.0)};  // the yarns run from x = 4 to 8
  std::vector<PlaneElement> layer;
  PatchRequest request = request_at({4.0, 4.0}, domain);
  request.whole_inputs_only = true;
  const PatchOutcome outcome = run(layer, request);
  EXPECT_EQ(outcome.inputs, 0);
  EXPECT_TRUE(layer.empty());
  EXPECT_FALSE(outcome.covers(grid, {4.6, 5.6})) << "under the middle yarn, inside the patch";
  EXPECT_TRUE(outcome.covers(grid, {4.6, 4.85})) << "between yarns the swatch is empty";
}

// Over a curved base the plane is a chart: elements apart in it can meet in space (a patch that
// wraps around a thin part, normals converging over a concave one). Here the chart folds at
// x = 9, so a plate at x = 11 in the plane stands where the middle yarn goes in space (x = 6).
TEST_F(StepFixture, ElementsApartInThePlaneThatMeetInSpaceAreRefused) {
  const Rect2 domain{glm::dvec2(0.0), glm::dvec2(16.0)};
  std::vector<PlaneElement> layer{plate_at(11.0)};
  PatchRequest request = request_at({4.0, 4.0}, domain);
  request.to_space = [](const TriMesh& mesh) {
    TriMesh folded = mesh;
    for (Vec3& p : folded.positions)
      if (p.x > 9.0) p.x = 17.0 - p.x;
    return folded;
  };
  const PatchOutcome outcome = run(layer, request);
  EXPECT_EQ(counts.rejected_inputs, 1);
  EXPECT_EQ(outcome.added.size(), 2u);
  // Without the fold nothing is in the way.
  std::vector<PlaneElement> flat_layer{layer[0]};
  counts = {};
  request.to_space = [](const TriMesh& mesh) { return mesh; };
  EXPECT_EQ(run(flat_layer, request).added.size(), 3u);
  EXPECT_EQ(counts.rejected_inputs, 0);
}

// A yarn four swatch lengths long takes part through its part in the window x >= 1: the vertices
// joining that part to the rest are pinned. The step stitches the swatch's yarn onto its end; the
// part goes back by the pinned vertices' exact positions and the whole yarn is one closed tube.
TEST_F(StepFixture, LongElementTakesPartThroughAPinnedPart) {
  const Rect2 domain{glm::dvec2(-20.0), glm::dvec2(20.0)};
  grid.origin = glm::dvec2(-8.0);
  TriMesh yarn;
  add_tube(yarn, -10.0, 6.0, 4.0 + (swatch.element_bounds[0].lo.y + swatch.element_bounds[0].hi.y) / 2.0, 0);
  yarn.elements.clear();
  // The part: faces whose vertices all lie at x >= 1.
  std::vector<uint8_t> in_part(yarn.num_faces(), 0);
  std::vector<int32_t> part_vertex(yarn.num_vertices(), -1);
  std::vector<uint8_t> used_outside(yarn.num_vertices(), 0);
  PlaneElement part;
  std::vector<int32_t> original;  // part vertex -> yarn vertex
  for (size_t f = 0; f < yarn.num_faces(); ++f) {
    const Tri& t = yarn.triangles[f];
    if (!(yarn.positions[t[0]].x >= 1.0 && yarn.positions[t[1]].x >= 1.0 && yarn.positions[t[2]].x >= 1.0)) {
      for (int32_t v : t) used_outside[v] = 1;
      continue;
    }
    in_part[f] = 1;
    Tri local;
    for (int k = 0; k < 3; ++k) {
      if (part_vertex[t[k]] < 0) {
        part_vertex[t[k]] = static_cast<int32_t>(part.mesh.positions.size());
        part.mesh.positions.push_back(yarn.positions[t[k]]);
        original.push_back(t[k]);
      }
      local[k] = part_vertex[t[k]];
    }
    part.mesh.triangles.push_back(local);
  }
  part.pinned.assign(part.mesh.positions.size(), 0);
  for (size_t k = 0; k < original.size(); ++k) part.pinned[k] = used_outside[original[k]];
  ASSERT_EQ(std::count(part.pinned.begin(), part.pinned.end(), 1), kSides);
  part.bounds = xy_bounds(part.mesh);
  std::vector<PlaneElement> layer{part};

  // The swatch's first yarn continues the long one from x = 4 to x = 8.
  run(layer, request_at({4.0, 4.0}, domain));
  ASSERT_TRUE(layer[0].changed) << "stitched " << counts.stitched << ", yielded " << counts.kept;
  ASSERT_EQ(counts.stitched, 1);
  const TriMesh& merged = layer[0].mesh;

  // Put the part back: the rest's faces, then the new part's, joined where positions coincide.
  TriMesh whole;
  std::map<std::tuple<double, double, double>, int32_t> index_of;
  const auto add_vertex = [&](const Vec3& p) {
    const auto [it, fresh] =
        index_of.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<int32_t>(whole.positions.size()));
    if (fresh) whole.positions.push_back(p);
    return it->second;
  };
  for (size_t f = 0; f < yarn.num_faces(); ++f)
    if (!in_part[f]) {
      const Tri& t = yarn.triangles[f];
      whole.triangles.push_back({add_vertex(yarn.positions[t[0]]), add_vertex(yarn.positions[t[1]]),
                                 add_vertex(yarn.positions[t[2]])});
    }
  const size_t rest_vertices = whole.positions.size();
  for (const Tri& t : merged.triangles)
    whole.triangles.push_back({add_vertex(merged.positions[t[0]]), add_vertex(merged.positions[t[1]]),
                               add_vertex(merged.positions[t[2]])});
  EXPECT_LT(rest_vertices, whole.positions.size());
  const SurfaceReport report = inspect_surface(whole);
  EXPECT_TRUE(report.closed_manifold()) << report.boundary_edges << " boundary edges";
  EXPECT_EQ(report.components, 1);
  double lo = 1e300, hi = -1e300;
  for (const Vec3& p : whole.positions) {
    lo = std::min(lo, p.x);
    hi = std::max(hi, p.x);
  }
  EXPECT_EQ(lo, -10.0) << "the rest of the yarn stays where it was";
  EXPECT_GT(hi, 7.5) << "the swatch's yarn continues the long one";
}

}  // namespace
}  // namespace meshquilt

namespace meshquilt {
namespace {

// Closed boxes at the corners of a 10 x 10 footprint and one inside; an open box on its right
// side (cut by the crop) and a small open one in the middle (open, but not cut).
TriMesh cropped_boxes() {
  return join_elements({test::box({0, 0, 0}, {0.5, 0.5, 0.5}), test::box({9.5, 0, 0}, {10, 0.5, 0.5}),
                        test::box({0, 9.5, 0}, {0.5, 10, 0.5}), test::box({9.5, 9.5, 0}, {10, 10, 0.5}),
                        test::box({2, 2, 0}, {3, 3, 0.5}), test::open_box({9.6, 4, 0}, {10, 5, 0.5}),
                        test::open_box({4, 4, 0}, {4.5, 4.5, 0.5})});
}

TEST(PrepareSwatch, LeavesOutOpenElementsCutByTheBorderWhereOthersAreClosed) {
  const TriMesh swatch = cropped_boxes();
  const QuiltSwatch prepared = prepare_swatch(swatch);
  EXPECT_EQ(prepared.cut_elements, 1);
  EXPECT_EQ(prepared.elements.size(), 6u);
  EXPECT_NEAR(prepared.extent.x, 10.0, 1e-12);
  EXPECT_NEAR(prepared.extent.y, 10.0, 1e-12);
}

TEST(PrepareSwatch, LeavesOutCutElementsOfACropTurnedInXY) {
  // The same swatch turned by 30 degrees: the crop's side is no longer along an axis.
  TriMesh swatch = cropped_boxes();
  const double c = std::cos(0.5236), s = std::sin(0.5236);
  for (Vec3& p : swatch.positions) p = Vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
  const QuiltSwatch prepared = prepare_swatch(swatch);
  EXPECT_EQ(prepared.cut_elements, 1);
  EXPECT_EQ(prepared.elements.size(), 6u);
}

TEST(PrepareSwatch, KeepsASwatchOfOpenElementsOnly) {
  const TriMesh sheet =
      join_elements({test::open_box({0, 0, 0}, {2, 2, 0.5}), test::open_box({3, 0, 0}, {5, 2, 0.5})});
  const QuiltSwatch prepared = prepare_swatch(sheet);
  EXPECT_EQ(prepared.cut_elements, 0);
  EXPECT_EQ(prepared.elements.size(), 2u);
}

TEST(PrepareSwatch, NotesWhetherAnElementPassesThroughItself) {
  EXPECT_TRUE(prepare_swatch(cropped_boxes()).unfolded_elements);
  EXPECT_FALSE(prepare_swatch(test::folded_torus()).unfolded_elements);
  EXPECT_TRUE(prepare_swatch(test::torus(1.0, 0.3)).unfolded_elements);
}

}  // namespace
}  // namespace meshquilt
