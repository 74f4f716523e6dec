// The sweep against closed forms, and the painter against samples whose right answer is known:
// a constant colour, and stripes that must come back as a translated copy of themselves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "paint/surface_paint.h"
#include "paint/sweep_batches.h"
#include "paint/sweep_order.h"
#include "support/backends.h"
#include "support/surface_fixtures.h"
#include "surface/guidance_field.h"
#include "surface/surface_types.h"

namespace meshquilt {
namespace {

class SurfacePaint : public test::BackendTest {};

std::vector<FieldConstraint> along(const TriMesh& mesh, const Vec3& d) {
  std::vector<FieldConstraint> constraints;
  for (size_t v = 0; v < mesh.num_vertices(); v += 7) constraints.push_back({static_cast<int32_t>(v), d});
  return constraints;
}

TEST(SweepFunction, IsTheCoordinateAlongAConstantFieldOnAPlane) {
  const TriMesh plane = test::flat_grid(12, 9, 0.5, 0.3, 4);
  const BaseSurface surface(plane);
  const Vec3 d = glm::normalize(Vec3(2.0, 1.0, 0.0));
  const std::vector<Vec3> directions(plane.num_vertices(), d);
  const std::vector<double> s = sweep_function(surface, directions);
  // grad s = d exactly: s is the coordinate along d plus a constant.
  const double c = s[0] - glm::dot(plane.positions[0], d);
  for (size_t v = 0; v < plane.num_vertices(); ++v) EXPECT_NEAR(s[v] - glm::dot(plane.positions[v], d), c, 1e-6);
  const std::vector<int32_t> order = sweep_order(s);
  for (size_t k = 1; k < order.size(); ++k)
    EXPECT_LE(glm::dot(plane.positions[order[k - 1]], d), glm::dot(plane.positions[order[k]], d) + 1e-6);
}

TEST(SweepFunction, RisesAlongTheFieldOnASphere) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface surface(sphere);
  const GuidanceField field = interpolate_field(surface, {});
  const std::vector<double> s = sweep_function(surface, field.directions);
  int along = 0, rising = 0;
  for (size_t v = 0; v < sphere.num_vertices(); ++v)
    for (const auto& [w, length] : surface.edges[v]) {
      const Vec3 e = (sphere.positions[w] - sphere.positions[v]) / length;
      if (glm::dot(e, field.directions[v]) < 0.9) continue;
      ++along;
      rising += s[w] > s[v];
    }
  ASSERT_GT(along, 100);
  EXPECT_GT(static_cast<double>(rising) / along, 0.95);
}

ColourImage stripes() {
  // Period 8 along x: 4 red, 4 blue.
  ColourImage image;
  image.width = image.height = 16;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) image.rgb.push_back(x % 8 < 4 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1));
  return image;
}

constexpr double kStripePixelsPerUnit = 16.0;

// stripes() over `plane` along the field d, at kStripePixelsPerUnit.
PaintResult paint_stripes(const TriMesh& plane, const Vec3& d, engine::Device& device) {
  PaintOptions options;
  options.pixels_per_unit = kStripePixelsPerUnit;
  return paint_surface(plane, stripes(), along(plane, d), options, device);
}

glm::dvec3 colour_of(const PaintResult& p, size_t v) {
  const auto& c = p.mesh.colors[v];
  return glm::dvec3(c[0], c[1], c[2]) / 255.0;
}

// The share of vertices painted with the sample at x * pixels_per_unit + phase, to rounding, for
// one phase for the whole plane (the first vertex's, drawn at random): a translated copy along x.
double share_of_one_translated_copy(const PaintResult& painted, const ColourImage& image, double pixels_per_unit) {
  const double phase = painted.source[0].x - painted.mesh.positions[0].x * pixels_per_unit;
  size_t close = 0;
  for (size_t v = 0; v < painted.mesh.num_vertices(); ++v) {
    const glm::dvec3 expected = image.sample({painted.mesh.positions[v].x * pixels_per_unit + phase, 0.5});
    close += glm::length(colour_of(painted, v) - expected) < 1.0 / 255.0;
  }
  return static_cast<double>(close) / static_cast<double>(painted.mesh.num_vertices());
}

TEST_P(SurfacePaint, AConstantSampleGivesItsColourEverywhere) {
  ColourImage image;
  image.width = image.height = 8;
  image.rgb.assign(64, glm::dvec3(0.2, 0.4, 0.6));
  PaintOptions options;
  options.pixels_per_unit = 8.0;
  const PaintResult painted = paint_surface(test::icosphere(2), image, {}, options, device());
  EXPECT_GT(painted.levels, 0);
  ASSERT_EQ(painted.mesh.colors.size(), painted.mesh.num_vertices());
  for (const auto& c : painted.mesh.colors) EXPECT_EQ(c, (std::array<uint8_t, 3>{51, 102, 153}));
}

TEST_P(SurfacePaint, StripesOnAPlaneComeBackAsATranslatedCopy) {
  // A plane one sample pixel per grid step, the field along x: the painted colours are the
  // stripes at x * pixels_per_unit + phase for one phase, up to the blend at stripe borders.
  const TriMesh plane = test::flat_grid(40, 20, 1.0 / 16.0, 0.0);
  const PaintResult painted = paint_stripes(plane, Vec3(1, 0, 0), device());
  EXPECT_GT(share_of_one_translated_copy(painted, stripes(), kStripePixelsPerUnit), 0.99);
  // Grid neighbours along x in the same stripe (more red than blue, or less): 3 in 4 when the
  // stripes run across x, all of them when the field is turned a quarter and they run along x.
  const auto same_along_x = [&](const PaintResult& p) {
    size_t same = 0, pairs = 0;
    for (size_t v = 0; v < p.mesh.num_vertices(); ++v)
      for (size_t w = 0; w < p.mesh.num_vertices(); ++w) {
        const Vec3 d = p.mesh.positions[w] - p.mesh.positions[v];
        if (std::abs(d.x - 1.0 / 16.0) > 1e-9 || std::abs(d.y) > 1e-9) continue;
        ++pairs;
        same += (colour_of(p, v).x > colour_of(p, v).z) == (colour_of(p, w).x > colour_of(p, w).z);
      }
    return static_cast<double>(same) / static_cast<double>(pairs);
  };
  EXPECT_NEAR(same_along_x(painted), 0.75, 0.05);
  const PaintResult turned = paint_stripes(plane, Vec3(0, 1, 0), device());
  EXPECT_GT(same_along_x(turned), 0.95);
}

TEST_P(SurfacePaint, ABaseDenserThanTheSampleReadsAVertexACellAndStillCopies) {
  // Four grid steps a pixel, sixteen vertices a pixel square: a 7-pixel window round a vertex
  // holds about 600 of them, and reading all would cost that much per candidate. It may read one
  // per half-pixel cell, at most 15 x 15, and the stripes still come back as one translated copy.
  const TriMesh plane = test::flat_grid(160, 40, 1.0 / 64.0, 0.0);
  const PaintResult painted = paint_stripes(plane, Vec3(1, 0, 0), device());
  ASSERT_EQ(painted.mesh.num_vertices(), plane.num_vertices());
  ASSERT_GT(painted.visits, 0u);
  EXPECT_LE(static_cast<double>(painted.neighbours) / static_cast<double>(painted.visits), 15.0 * 15.0);
  EXPECT_GT(static_cast<double>(painted.neighbours) / static_cast<double>(painted.visits), 50.0);
  EXPECT_GT(share_of_one_translated_copy(painted, stripes(), kStripePixelsPerUnit), 0.99);
}

TEST_P(SurfacePaint, PaintsAlongSynthsFieldWhateverTheRefinement) {
  // One direction held on a coarse plane: synth's smoothest field holding it is that direction
  // everywhere. Spread over the refined mesh instead, it would turn back to the default within a
  // few fine edges.
  const TriMesh plane = test::flat_grid(8, 8, 0.125, 0.0);
  const std::vector<FieldConstraint> held{{40, glm::normalize(Vec3(1, 1, 0))}};
  ColourImage image;
  image.width = image.height = 16;
  image.rgb.assign(256, glm::dvec3(0.5));
  PaintOptions options;
  options.pixels_per_unit = 64.0;
  const PaintResult painted = paint_surface(plane, image, held, options, device());
  ASSERT_GE(painted.levels, 3);
  ASSERT_EQ(painted.directions.size(), painted.mesh.num_vertices());
  // Every vertex of every split runs along the held direction.
  double worst = 0.0;
  for (const Vec3& d : painted.directions) worst = std::max(worst, std::acos(std::min(1.0, glm::dot(d, held[0].direction))));
  EXPECT_LT(worst, 1.0 * std::numbers::pi / 180.0);
}

TEST_P(SurfacePaint, IsDeterministicForASeedAndRefusesBadOptions) {
  const TriMesh sphere = test::icosphere(2);
  PaintOptions options;
  options.pixels_per_unit = 6.0;
  const ColourImage image = stripes();
  const PaintResult a = paint_surface(sphere, image, {}, options, device());
  const PaintResult b = paint_surface(sphere, image, {}, options, device());
  EXPECT_EQ(a.mesh.colors, b.mesh.colors);
  options.seed = 2;
  EXPECT_NE(paint_surface(sphere, image, {}, options, device()).mesh.colors, a.mesh.colors);
  options.window = 4;
  EXPECT_THROW(paint_surface(sphere, image, {}, options, device()), InputError);
  options.window = 7;
  options.pixels_per_unit = 1e6;
  EXPECT_THROW(paint_surface(sphere, image, {}, options, device()), InputError);
}

// Batches side by side give the sequential sweep's colours, and the back ends choose alike:
// scored in float, the choice is made in double.
TEST_P(SurfacePaint, BatchesAndBackEndsGiveTheSweepsColours) {
  const TriMesh sphere = test::icosphere(2);
  ColourImage image;
  image.width = image.height = 24;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      image.rgb.emplace_back(0.5 + 0.5 * std::sin(0.9 * x + 0.3 * y), 0.5 + 0.5 * std::cos(0.4 * x * y), (x ^ y) % 5 / 4.0);
  PaintOptions options;
  options.pixels_per_unit = 12.0;
  options.max_batch = 1;
  std::string why;
  engine::Device* cpu = shared_device(engine::Backend::cpu, &why);
  ASSERT_NE(cpu, nullptr) << why;
  const PaintResult sequential = paint_surface(sphere, image, {}, options, *cpu);
  options.max_batch = 4096;
  const PaintResult batched = paint_surface(sphere, image, {}, options, device());
  ASSERT_GE(sequential.levels, 2);
  EXPECT_EQ(batched.source, sequential.source);
  EXPECT_EQ(batched.mesh.colors, sequential.mesh.colors);
  options.max_batch = 7;
  EXPECT_EQ(paint_surface(sphere, image, {}, options, device()).source, sequential.source);
}

TEST_P(SurfacePaint, ReportsProgressUpToEveryVisit) {
  PaintOptions options;
  options.pixels_per_unit = 10.0;
  std::vector<std::pair<size_t, size_t>> calls;
  options.progress = [&](size_t done, size_t total) { calls.emplace_back(done, total); };
  const PaintResult painted = paint_surface(test::icosphere(2), stripes(), {}, options, device());
  ASSERT_GE(painted.levels, 2);
  ASSERT_EQ(calls.size(), painted.batches);
  for (size_t k = 1; k < calls.size(); ++k) {
    EXPECT_GT(calls[k].first, calls[k - 1].first);
    EXPECT_EQ(calls[k].second, calls[0].second);
  }
  EXPECT_EQ(calls.back().first, painted.visits);
  EXPECT_EQ(calls.back().second, painted.visits);
}

TEST_P(SurfacePaint, StopsAtTheBatchItIsCancelledIn) {
  PaintOptions options;
  options.pixels_per_unit = 10.0;
  CancelToken token;
  options.cancel = &token;
  size_t calls = 0;
  options.progress = [&](size_t, size_t) {
    if (++calls == 3) token.cancel();
  };
  EXPECT_THROW(paint_surface(test::icosphere(2), stripes(), {}, options, device()), Cancelled);
  EXPECT_EQ(calls, 3u);
}

TEST(SweepBatches, RunSideBySideOnlyWhatTheSweepWouldNotTellApart) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface surface(sphere);
  const WindowNeighbours windows = window_neighbours(surface, 0.3);
  std::vector<Vec3> directions(sphere.num_vertices());
  for (size_t v = 0; v < directions.size(); ++v) {
    const Vec3 n = surface.vertex_normals[v];
    directions[v] = glm::normalize(glm::cross(n, std::abs(n.z) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0)));
  }
  const std::vector<int32_t> order = sweep_order(sweep_function(surface, directions));
  std::vector<int32_t> position(order.size());
  for (size_t k = 0; k < order.size(); ++k) position[order[k]] = static_cast<int32_t>(k);
  // Brute force: window neighbours from distances alone (the sphere's small windows are convex).
  const auto within = [&](int32_t a, int32_t b) {
    for (int64_t k = windows.first[a]; k < windows.first[a + 1]; ++k)
      if (windows.vertices[k] == b) return true;
    return false;
  };
  for (int32_t a = 0; a < 40; ++a)
    for (int32_t b = 0; b < static_cast<int32_t>(sphere.num_vertices()); ++b) {
      if (a != b) {
        EXPECT_EQ(within(a, b), glm::distance(sphere.positions[a], sphere.positions[b]) <= 0.3) << a << " " << b;
      }
    }
  const std::vector<std::vector<int32_t>> batches = sweep_batches(order, windows, 1000);
  ASSERT_LT(batches.size(), order.size() / 4);  // side by side, not one at a time
  std::vector<int32_t> batch_of(order.size(), -1);
  for (size_t i = 0; i < batches.size(); ++i)
    for (int32_t v : batches[i]) {
      ASSERT_EQ(batch_of[v], -1) << v;
      batch_of[v] = static_cast<int32_t>(i);
    }
  // A vertex runs after every earlier one it reads, and never before an earlier one reading it.
  for (int32_t v = 0; v < static_cast<int32_t>(order.size()); ++v) {
    ASSERT_GE(batch_of[v], 0);
    for (int64_t k = windows.first[v]; k < windows.first[v + 1]; ++k) {
      const int32_t u = windows.vertices[k];
      if (position[u] < position[v]) {
        EXPECT_LT(batch_of[u], batch_of[v]);
      } else {
        EXPECT_GE(batch_of[u], batch_of[v]);
      }
    }
  }
  EXPECT_EQ(sweep_batches(order, windows, 1).size(), order.size());
  EXPECT_EQ(sweep_batches(order, windows, 1)[5], std::vector<int32_t>{order[5]});
}

MESHQUILT_ON_BACKENDS(SurfacePaint);

}  // namespace
}  // namespace meshquilt
