#include "paint/detail_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Sparse>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "numerics/sparse_solve.h"
#include "surface/conformal_patch.h"
#include "surface/surface_types.h"

namespace meshquilt {

std::vector<double> extract_detail(const TriMesh& model, double smoothing) {
  const size_t n = model.num_vertices();
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> mass(n, 0.0);
  for (const Tri& t : model.triangles) {
    const double area =
        0.5 * glm::length(glm::cross(model.positions[t[1]] - model.positions[t[0]], model.positions[t[2]] - model.positions[t[0]]));
    for (int k = 0; k < 3; ++k) {
      mass[t[k]] += area / 3.0;
      // The edge opposite corner k, weighted by this face's half cotangent.
      const double w = smoothing * smoothing * half_cotangent(model, t, k);
      const int32_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      triplets.emplace_back(a, a, w);
      triplets.emplace_back(b, b, w);
      triplets.emplace_back(a, b, -w);
      triplets.emplace_back(b, a, -w);
    }
  }
  double largest = 0.0;
  for (double m : mass) largest = std::max(largest, m);
  Eigen::MatrixXd rhs(n, 3);
  for (size_t v = 0; v < n; ++v) {
    // A vertex on no face keeps its place.
    const double m = std::max(mass[v], 1e-12 * largest + 1e-300);
    triplets.emplace_back(v, v, m);
    for (int c = 0; c < 3; ++c) rhs(v, c) = m * model.positions[v][c];
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd smooth = solve_positive_definite(A, rhs, "detail smoothing");
  TriMesh smoothed = model;
  for (size_t v = 0; v < n; ++v) smoothed.positions[v] = Vec3(smooth(v, 0), smooth(v, 1), smooth(v, 2));
  const std::vector<Vec3> normals = vertex_normals(smoothed);
  std::vector<double> heights(n);
  for (size_t v = 0; v < n; ++v) heights[v] = glm::dot(model.positions[v] - smoothed.positions[v], normals[v]);
  return heights;
}

namespace {

int32_t nearest_vertex(const TriMesh& model, const Vec3& p) {
  int32_t best = 0;
  double best_distance = std::numeric_limits<double>::max();
  for (size_t v = 0; v < model.num_vertices(); ++v) {
    const double d = glm::distance(model.positions[v], p);
    if (d < best_distance) {
      best_distance = d;
      best = static_cast<int32_t>(v);
    }
  }
  return best;
}

// Whether every pixel centre of a square of half side `half` about the origin lies over the patch.
bool square_fits(const SurfacePatch& patch, double half, int pixels) {
  const double step = 2.0 * half / pixels;
  for (int y = 0; y < pixels; ++y)
    for (int x = 0; x < pixels; ++x)
      if (!patch.locate({-half + (x + 0.5) * step, -half + (y + 0.5) * step})) return false;
  return true;
}

}  // namespace

DetailImage detail_image(const TriMesh& model, const std::vector<double>& heights, const Vec3& centre, double radius,
                         int pixels) {
  if (pixels < 8) throw InputError("{region}: expected at least 8 pixels a side", ErrorKind::invalid_option);
  const BaseSurface surface(model);
  const int32_t v = nearest_vertex(model, centre);
  if (surface.vertex_faces[v].empty()) throw InputError("{region}: its centre is on no face", ErrorKind::invalid_option);
  const int32_t face = surface.vertex_faces[v].front();
  const Tri& t = model.triangles[face];
  const glm::dvec2 bary = t[1] == v ? glm::dvec2(1.0, 0.0) : t[2] == v ? glm::dvec2(0.0, 1.0) : glm::dvec2(0.0);
  SurfacePatch patch = grow_conformal_patch(surface, {face, bary}, radius);
  if (patch.flipped_faces > 0)
    throw InputError("{region}: the model round it folds when flattened; choose a smaller or smoother region",
                     ErrorKind::invalid_option);
  patch.index();
  // The largest square the ball holds: from the inscribed square of a disk of the radius, shrunk.
  double half = radius / std::sqrt(2.0);
  while (half > 1e-3 * radius && !square_fits(patch, half, pixels)) half *= 0.9;
  if (!square_fits(patch, half, pixels))
    throw InputError("{region}: no square fits in the flattened region", ErrorKind::invalid_option);
  std::vector<double> grid(static_cast<size_t>(pixels) * pixels);
  const double step = 2.0 * half / pixels;
  for (int y = 0; y < pixels; ++y)
    for (int x = 0; x < pixels; ++x) {
      const SurfacePoint p = *patch.locate({-half + (x + 0.5) * step, -half + (y + 0.5) * step});
      const Tri& f = model.triangles[p.face];
      grid[static_cast<size_t>(y) * pixels + x] =
          (1.0 - p.bary.x - p.bary.y) * heights[f[0]] + p.bary.x * heights[f[1]] + p.bary.y * heights[f[2]];
    }
  DetailImage result;
  result.low = *std::min_element(grid.begin(), grid.end());
  result.high = *std::max_element(grid.begin(), grid.end());
  const double span = result.high > result.low ? result.high - result.low : 1.0;
  result.image.width = result.image.height = pixels;
  result.image.rgb.reserve(grid.size());
  for (double h : grid) result.image.rgb.emplace_back((h - result.low) / span);
  result.pixels_per_unit = 1.0 / step;
  return result;
}

Vec3 richest_detail_centre(const TriMesh& model, const std::vector<double>& heights, double radius) {
  constexpr size_t kCandidates = 24;
  const size_t n = model.num_vertices();
  Vec3 best_centre = model.positions.empty() ? Vec3(0.0) : model.positions.front();
  double best_spread = -1.0;
  for (size_t c = 0; c < kCandidates && c < n; ++c) {
    const Vec3& centre = model.positions[c * n / std::min(n, kCandidates)];
    double sum = 0.0, sum_squares = 0.0;
    int count = 0;
    for (size_t v = 0; v < n; ++v) {
      if (glm::distance(model.positions[v], centre) > radius) continue;
      sum += heights[v];
      sum_squares += heights[v] * heights[v];
      ++count;
    }
    if (count < 16) continue;
    const double spread = sum_squares / count - (sum / count) * (sum / count);
    if (spread > best_spread) {
      best_spread = spread;
      best_centre = centre;
    }
  }
  return best_centre;
}

DetailSample detail_sample(const TriMesh& model, double smoothing, const std::optional<DetailRegion>& region,
                           int pixels) {
  const double diagonal = glm::length(bounding_box(model.positions).extent());
  DetailSample out;
  out.smoothing = smoothing > 0.0 ? smoothing : 0.01 * diagonal;
  const std::vector<double> heights = extract_detail(model, out.smoothing);
  out.radius = region ? region->radius : 0.1 * diagonal;
  if (!(out.radius > 0.0)) throw InputError("{region}: expected a positive radius", ErrorKind::invalid_option);
  out.centre = region ? region->centre : richest_detail_centre(model, heights, out.radius);
  out.detail = detail_image(model, heights, out.centre, out.radius, pixels);
  if (!(out.detail.high - out.detail.low > 1e-9 * diagonal))
    throw InputError("{from}: no detail over the region sampled: the model is as smooth there as its smoothed self",
                     ErrorKind::invalid_option);
  return out;
}

}  // namespace meshquilt
