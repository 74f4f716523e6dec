#include "mesh/convex_outline.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace meshquilt {
namespace {

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Distance from p to the segment [a, b].
double segment_distance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double s = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + s * ab));
}

}  // namespace

ConvexOutline::ConvexOutline(const std::vector<Vec3>& points) : ConvexOutline([&] {
  std::vector<glm::dvec2> xy;
  xy.reserve(points.size());
  for (const Vec3& p : points) xy.emplace_back(p.x, p.y);
  return xy;
}()) {}

ConvexOutline::ConvexOutline(std::vector<glm::dvec2> sorted) {
  std::sort(sorted.begin(), sorted.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 3) {
    corners_ = sorted;
    return;
  }
  std::vector<glm::dvec2> hull(2 * sorted.size());
  size_t k = 0;
  for (const glm::dvec2& p : sorted) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (size_t i = sorted.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0.0) --k;
    hull[k++] = sorted[i];
  }
  hull.resize(k - 1);
  corners_ = std::move(hull);
}

bool ConvexOutline::contains(const glm::dvec2& p, double margin) const {
  if (corners_.empty()) return false;
  if (corners_.size() < 3) {
    const glm::dvec2& b = corners_.back();
    return segment_distance(p, corners_.front(), b) <= margin;
  }
  for (size_t i = 0; i < corners_.size(); ++i) {
    const glm::dvec2& a = corners_[i];
    const glm::dvec2& b = corners_[(i + 1) % corners_.size()];
    // Outward distance of p past the edge's line; the hull is counter-clockwise.
    if (-cross(a, b, p) / glm::length(b - a) > margin) return false;
  }
  return true;
}

double ConvexOutline::boundary_distance(const glm::dvec2& p) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < corners_.size(); ++i)
    nearest = std::min(nearest, segment_distance(p, corners_[i], corners_[(i + 1) % corners_.size()]));
  return nearest;
}

double ConvexOutline::width() const {
  if (corners_.size() < 3) return 0.0;
  // The narrowest direction is normal to an edge (rotating calipers); corners are few.
  double narrowest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < corners_.size(); ++i) {
    const glm::dvec2& a = corners_[i];
    const glm::dvec2& b = corners_[(i + 1) % corners_.size()];
    const double length = glm::length(b - a);
    double farthest = 0.0;
    for (const glm::dvec2& c : corners_) farthest = std::max(farthest, cross(a, b, c) / length);
    narrowest = std::min(narrowest, farthest);
  }
  return narrowest;
}

}  // namespace meshquilt
