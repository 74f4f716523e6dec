#include "inspect/ring_links.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "inspect/element_statistics.h"
#include "mesh/disjoint_sets.h"
#include "numerics/symmetric_eigen.h"
#include "spatial/box_grid.h"

namespace meshquilt {
namespace {

// The solid angle (over 4 pi, signed) under which segment b1-b2 sees segment a1-a2: one term of
// the Gauss linking integral of two polygons.
double segment_pair_term(const Vec3& a1, const Vec3& a2, const Vec3& b1, const Vec3& b2) {
  const Vec3 r13 = b1 - a1, r14 = b2 - a1, r23 = b1 - a2, r24 = b2 - a2;
  Vec3 n[4] = {glm::cross(r13, r14), glm::cross(r14, r24), glm::cross(r24, r23), glm::cross(r23, r13)};
  for (Vec3& k : n) {
    const double length = glm::length(k);
    if (!(length > 0.0)) return 0.0;  // degenerate: the segments' lines meet or a segment is a point
    k /= length;
  }
  double omega = 0.0;
  for (int k = 0; k < 4; ++k) omega += std::asin(std::clamp(glm::dot(n[k], n[(k + 1) % 4]), -1.0, 1.0));
  const double side = glm::dot(glm::cross(b2 - b1, a2 - a1), r13);
  return side > 0.0 ? omega : (side < 0.0 ? -omega : 0.0);
}

// The q-quantile of sorted, non-empty values: the one nearest rank q x (n - 1).
double nearest_rank(const std::vector<double>& sorted, double q) {
  return sorted[static_cast<size_t>(std::lround(q * static_cast<double>(sorted.size() - 1)))];
}

}  // namespace

std::vector<RingCentreLine> ring_centre_lines(const TriMesh& mesh, const std::vector<int32_t>& face_element,
                                              int32_t elements, int bins) {
  std::vector<std::vector<int32_t>> vertices(static_cast<size_t>(elements));
  {
    std::vector<int32_t> element_of(mesh.num_vertices(), -1);
    for (size_t f = 0; f < mesh.num_faces(); ++f)
      for (int32_t v : mesh.triangles[f]) element_of[v] = face_element[f];
    for (size_t v = 0; v < element_of.size(); ++v)
      if (element_of[v] >= 0) vertices[element_of[v]].push_back(static_cast<int32_t>(v));
  }
  std::vector<RingCentreLine> lines(static_cast<size_t>(elements));
  for (int32_t e = 0; e < elements; ++e) {
    const std::vector<int32_t>& vs = vertices[e];
    if (vs.size() < 3) continue;
    RingCentreLine& line = lines[e];
    for (int32_t v : vs) line.centre += mesh.positions[v];
    line.centre /= static_cast<double>(vs.size());
    Symmetric3 covariance{};
    for (int32_t v : vs) {
      const Vec3 d = mesh.positions[v] - line.centre;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) covariance[i][j] += d[i] * d[j];
    }
    line.normal = glm::normalize(symmetric_eigenvectors(covariance)[0]);
    // An in-plane frame (u, w) for the angles.
    const Vec3 helper = std::abs(line.normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(line.normal, helper)), w = glm::cross(line.normal, u);
    std::vector<Vec3> sum(static_cast<size_t>(bins), Vec3(0.0));
    std::vector<int> count(static_cast<size_t>(bins), 0);
    for (int32_t v : vs) {
      const Vec3 d = mesh.positions[v] - line.centre;
      const double angle = std::atan2(glm::dot(d, w), glm::dot(d, u));
      int bin = static_cast<int>(std::floor((angle + std::numbers::pi) / (2.0 * std::numbers::pi) * bins));
      bin = std::clamp(bin, 0, bins - 1);
      sum[bin] += mesh.positions[v];
      ++count[bin];
    }
    for (int b = 0; b < bins; ++b)
      if (count[b] > 0) line.points.push_back(sum[b] / static_cast<double>(count[b]));
    for (const Vec3& p : line.points) line.radius += glm::length(p - line.centre);
    if (!line.points.empty()) line.radius /= static_cast<double>(line.points.size());
    // Second moments of the area the centre line encloses (polygon formulas): an ellipse's go
    // as the squares of its axes however its points are spaced.
    double area = 0.0, cx = 0.0, cy = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
    for (size_t i = 0; i < line.points.size(); ++i) {
      const Vec3 p = line.points[i] - line.centre, q = line.points[(i + 1) % line.points.size()] - line.centre;
      const double x0 = glm::dot(p, u), y0 = glm::dot(p, w), x1 = glm::dot(q, u), y1 = glm::dot(q, w);
      const double c = x0 * y1 - x1 * y0;
      area += c / 2.0;
      cx += (x0 + x1) * c / 6.0;
      cy += (y0 + y1) * c / 6.0;
      xx += c * (x0 * x0 + x0 * x1 + x1 * x1) / 12.0;
      yy += c * (y0 * y0 + y0 * y1 + y1 * y1) / 12.0;
      xy += c * (x0 * y1 + 2.0 * x0 * y0 + 2.0 * x1 * y1 + x1 * y0) / 24.0;
    }
    if (area == 0.0) continue;
    cx /= area;
    cy /= area;
    const double uu = xx / area - cx * cx, ww = yy / area - cy * cy, uw = xy / area - cx * cy;
    const double mean = 0.5 * (uu + ww), half = std::sqrt(0.25 * (uu - ww) * (uu - ww) + uw * uw);
    if (mean - half > 0.0) line.aspect = std::sqrt((mean + half) / (mean - half));
  }
  return lines;
}

double linking_number(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double total = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      total += segment_pair_term(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]);
  return total / (4.0 * std::numbers::pi);
}

RingsNear rings_near(const RingLinks& links, const std::vector<RingCentreLine>& lines, const std::vector<Vec3>& points,
                     double radius) {
  RingsNear near;
  std::vector<double> radii;
  for (size_t e = 0; e < lines.size(); ++e) {
    if (lines[e].points.empty()) continue;
    const bool close = std::any_of(points.begin(), points.end(),
                                   [&](const Vec3& p) { return glm::length(lines[e].centre - p) <= radius; });
    if (!close) continue;
    const int32_t count = links.links_per_ring[e];
    if (near.histogram.size() <= static_cast<size_t>(count)) near.histogram.resize(count + 1, 0);
    ++near.histogram[count];
    ++near.rings;
    near.loose_rings += count == 0;
    near.linked_to_3_share += count >= 3;
    radii.push_back(lines[e].radius);
  }
  if (near.rings == 0) return near;
  near.linked_to_3_share /= near.rings;
  std::sort(radii.begin(), radii.end());
  near.median_radius = median(radii);
  near.radius_p10 = nearest_rank(radii, 0.1);
  near.radius_p90 = nearest_rank(radii, 0.9);
  return near;
}

RingLinks ring_links(const TriMesh& mesh, const std::vector<int32_t>& face_element, int32_t elements) {
  return ring_links(ring_centre_lines(mesh, face_element, elements));
}

RingLinks ring_links(const std::vector<RingCentreLine>& lines) {
  RingLinks result;
  const auto elements = static_cast<int32_t>(lines.size());
  result.rings = elements;
  result.links_per_ring.assign(static_cast<size_t>(elements), 0);
  if (elements == 0) return result;
  std::vector<double> radii;
  double largest = 0.0;
  for (const RingCentreLine& line : lines) {
    radii.push_back(line.radius);
    largest = std::max(largest, line.radius);
  }
  result.median_radius = median(radii);
  std::sort(radii.begin(), radii.end());
  result.radius_p10 = nearest_rank(radii, 0.1);
  result.radius_p90 = nearest_rank(radii, 0.9);
  std::vector<double> aspects;
  for (const RingCentreLine& line : lines) aspects.push_back(line.aspect);
  result.median_aspect = median(aspects);
  std::sort(aspects.begin(), aspects.end());
  result.aspect_p90 = nearest_rank(aspects, 0.9);
  // Centre lines that can meet have centres within the sum of their radii; a margin covers the
  // binning's inward bias.
  const double margin = 0.25 * result.median_radius;
  BoxGrid grid(std::max(2.0 * largest + margin, 1e-12));
  for (int32_t e = 0; e < elements; ++e) grid.insert(e, lines[e].centre, lines[e].centre);
  DisjointSets pieces(elements);
  for (int32_t e = 0; e < elements; ++e) {
    if (lines[e].points.size() < 3) continue;
    const Vec3 reach(lines[e].radius + largest + margin);
    std::vector<int32_t> near;
    grid.for_each_cell(lines[e].centre - reach, lines[e].centre + reach, [&](const std::vector<int32_t>& items) {
      for (int32_t other : items)
        if (other > e) near.push_back(other);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (int32_t other : near) {
      const RingCentreLine& b = lines[other];
      if (b.points.size() < 3) continue;
      if (glm::length(b.centre - lines[e].centre) > lines[e].radius + b.radius + margin) continue;
      if (std::abs(linking_number(lines[e].points, b.points)) < 0.5) continue;
      result.links.emplace_back(e, other);
      ++result.links_per_ring[e];
      ++result.links_per_ring[other];
      pieces.unite(e, other);
    }
  }
  std::sort(result.links.begin(), result.links.end());
  std::vector<int32_t> piece_size(static_cast<size_t>(elements), 0);
  for (int32_t e = 0; e < elements; ++e) ++piece_size[pieces.find(e)];
  int32_t largest_piece = 0;
  for (int32_t size : piece_size) {
    if (size > 0) ++result.pieces;
    largest_piece = std::max(largest_piece, size);
  }
  result.largest_piece_share = static_cast<double>(largest_piece) / elements;
  int64_t total_links = 0;
  int32_t linked_to_3 = 0;
  for (int32_t k : result.links_per_ring) {
    if (static_cast<size_t>(k) >= result.histogram.size()) result.histogram.resize(k + 1, 0);
    ++result.histogram[k];
    total_links += k;
    if (k >= 3) ++linked_to_3;
    if (k == 0) ++result.loose_rings;
  }
  result.linked_to_3_share = static_cast<double>(linked_to_3) / elements;
  result.mean_links = static_cast<double>(total_links) / elements;
  return result;
}

}  // namespace meshquilt
