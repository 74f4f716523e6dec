// Detail extraction (Lai et al. 2005): a sphere bumped by a known pattern, built here, gives the
// pattern back as heights; a flat grid's linear heights come back as a linear ramp of the
// expected slope in the resampled image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "paint/detail_extraction.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

double bump(const Vec3& p) { return std::sin(10.0 * p.x) * std::sin(10.0 * p.y) * std::sin(10.0 * p.z); }

TEST(DetailExtraction, ABumpedSphereGivesItsBumpsBack) {
  TriMesh sphere = test::icosphere(5);
  const double amplitude = 0.02;
  std::vector<double> truth;
  for (Vec3& p : sphere.positions) {
    const Vec3 unit = glm::normalize(p);
    truth.push_back(amplitude * bump(unit));
    p = unit * (1.0 + truth.back());
  }
  const std::vector<double> heights = extract_detail(sphere, 0.4);
  ASSERT_EQ(heights.size(), truth.size());
  // The smoothed sphere shrinks: an offset. Less it, the heights are the bumps.
  double mean = 0.0;
  for (double h : heights) mean += h;
  mean /= static_cast<double>(heights.size());
  double error = 0.0, signal = 0.0;
  for (size_t v = 0; v < heights.size(); ++v) {
    error += (heights[v] - mean - truth[v]) * (heights[v] - mean - truth[v]);
    signal += truth[v] * truth[v];
  }
  EXPECT_LT(std::sqrt(error / signal), 0.15);
  EXPECT_GT(mean, 0.0);  // the smoothed copy lies inside
}

TEST(DetailExtraction, AFlatRampResamplesIntoALinearImageOfItsSlope) {
  // A 41 x 41 grid over [-1, 1]^2 with heights 0.3 x + 0.1 y: no smoothing needed.
  TriMesh grid;
  const int n = 41;
  std::vector<double> heights;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1.0 + 2.0 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
      grid.positions.emplace_back(x, y, 0.0);
      heights.push_back(0.3 * x + 0.1 * y);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      grid.triangles.push_back({a, b, d});
      grid.triangles.push_back({a, d, c});
    }
  const int pixels = 16;
  const DetailImage image = detail_image(grid, heights, Vec3(0.02, -0.01, 0.0), 0.8, pixels);
  ASSERT_EQ(image.image.width, pixels);
  // Least-squares plane through the pixel values, back in heights: v = a + b x + c y.
  double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, sv = 0, svx = 0, svy = 0;
  const int count = pixels * pixels;
  for (int y = 0; y < pixels; ++y)
    for (int x = 0; x < pixels; ++x) {
      const double v = image.low + image.image.at(x, y).r * (image.high - image.low);
      sx += x, sy += y, sv += v, sxx += x * x, syy += y * y, sxy += x * y, svx += v * x, svy += v * y;
    }
  const double cx = sx / count, cy = sy / count, cv = sv / count;
  const double vxx = sxx / count - cx * cx, vyy = syy / count - cy * cy, vxy = sxy / count - cx * cy;
  const double wx = svx / count - cv * cx, wy = svy / count - cv * cy;
  const double det = vxx * vyy - vxy * vxy;
  const double b = (wx * vyy - wy * vxy) / det, c = (wy * vxx - wx * vxy) / det;
  double residual = 0.0;
  for (int y = 0; y < pixels; ++y)
    for (int x = 0; x < pixels; ++x) {
      const double v = image.low + image.image.at(x, y).r * (image.high - image.low);
      residual = std::max(residual, std::abs(v - (cv + b * (x - cx) + c * (y - cy))));
    }
  EXPECT_LT(residual, 1e-6);
  // The slope per pixel is the slope per unit (|(0.3, 0.1)|, turned as the flattening pleases)
  // over the pixels per unit.
  EXPECT_NEAR(std::hypot(b, c) * image.pixels_per_unit, std::hypot(0.3, 0.1), 1e-3);
  EXPECT_GT(image.pixels_per_unit, pixels / 1.6);
}

TEST(DetailExtraction, TooFewPixelsAreRefused) {
  const TriMesh sphere = test::icosphere(3);
  const std::vector<double> heights(sphere.num_vertices(), 0.0);
  EXPECT_THROW(detail_image(sphere, heights, Vec3(1.0, 0.0, 0.0), 0.3, 4), InputError);
}

}  // namespace
}  // namespace meshquilt
