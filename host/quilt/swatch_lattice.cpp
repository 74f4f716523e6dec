#include "quilt/swatch_lattice.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "mesh/convex_outline.h"
#include "quilt/swatch_symmetry.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {


double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

glm::dvec2 turned(const glm::dvec2& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// Counts the elements a map of the plane (with its turn) sends among the centroids, and of
// those, the ones that land on an element of the same kind.
struct MapScore {
  int landed = 0, matched = 0;
  bool holds() const { return landed >= 2 && matched >= 0.9 * landed; }
};

class CentroidSet {
 public:
  explicit CentroidSet(std::vector<ElementShape> shapes) : shapes_(std::move(shapes)) {
    lo_ = glm::dvec2(std::numeric_limits<double>::max());
    hi_ = -lo_;
    // Elements whose centroids all but coincide (the two rings of a 2-in-2 link) are one place:
    // a step between them, a small fraction of an element's size, is no period.
    std::vector<double> sizes;
    for (const ElementShape& shape : shapes_) sizes.push_back(std::sqrt(shape.moments[0][0] + shape.moments[1][1]));
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    const double same_place = sizes.empty() ? 0.0 : 0.05 * sizes[sizes.size() / 2];
    double nearest = std::numeric_limits<double>::max();
    for (size_t i = 0; i < shapes_.size(); ++i) {
      lo_ = glm::min(lo_, shapes_[i].centre);
      hi_ = glm::max(hi_, shapes_[i].centre);
      for (size_t j = 0; j < i; ++j) {
        const double d = glm::distance(shapes_[i].centre, shapes_[j].centre);
        if (d > same_place) nearest = std::min(nearest, d);
      }
    }
    tolerance_ = nearest < std::numeric_limits<double>::max() ? 0.1 * nearest : 0.0;
  }

  const std::vector<ElementShape>& shapes() const { return shapes_; }
  double tolerance() const { return tolerance_; }
  glm::dvec2 middle() const { return 0.5 * (lo_ + hi_); }

  MapScore score(const std::function<glm::dvec2(const glm::dvec2&)>& map, double angle) const {
    MapScore s;
    for (const ElementShape& shape : shapes_) {
      const glm::dvec2 p = map(shape.centre);
      if (p.x < lo_.x - tolerance_ || p.y < lo_.y - tolerance_ || p.x > hi_.x + tolerance_ || p.y > hi_.y + tolerance_)
        continue;
      ++s.landed;
      for (const ElementShape& other : shapes_)
        if (glm::distance(p, other.centre) <= tolerance_ && shape.matches_turned(other, angle)) {
          ++s.matched;
          break;
        }
    }
    return s;
  }

 private:
  std::vector<ElementShape> shapes_;
  glm::dvec2 lo_{0.0}, hi_{0.0};
  double tolerance_ = 0.0;
};

// Points of the swatch's surface, and whether a map of the plane (z kept) puts them back on it:
// a yarn moved by a period lies along another yarn, not on its centroid, so a weave's periods
// show in its surface only.
class SurfaceSamples {
 public:
  explicit SurfaceSamples(const QuiltSwatch& swatch) : mesh_(swatch.mesh), bvh_(swatch.mesh) {
    const size_t n = swatch.mesh.positions.size();
    const size_t stride = std::max<size_t>(1, n / 3000);
    footprint_ = ConvexOutline(swatch.mesh.positions);
    for (size_t i = 0; i < n; i += stride) points_.push_back(swatch.mesh.positions[i]);
    tolerance_ = 0.05 * swatch.mean_edge;
    // Elements end at the border, in caps or cut ends that the pattern inside has not.
    margin_ = 2.0 * swatch.mean_edge;
  }

  size_t size() const { return points_.size(); }

  //! The map p -> turned(p, angle) + shift, its shift refined so the samples fall back on the
  //! surface: point-to-plane steps on the shift alone, from the nearest points within `reach`.
  //! A period measured between centroids of jittered or unevenly sampled elements is off by more
  //! than the surface allows (a crimped wire moved along itself leaves its own surface).
  glm::dvec2 refined_shift(double angle, glm::dvec2 shift, double reach) const {
    for (int round = 0; round < 8; ++round) {
      double a11 = 0.0, a12 = 0.0, a22 = 0.0, b1 = 0.0, b2 = 0.0;
      for (const Vec3& p : points_) {
        const glm::dvec2 q = turned(glm::dvec2(p), angle) + shift;
        if (outside(q)) continue;
        const Vec3 at(q, p.z);
        const ClosestPoint hit = bvh_.closest_point(at, reach);
        if (hit.face < 0) continue;
        const Tri& t = mesh_.triangles[hit.face];
        const Vec3 normal = glm::cross(mesh_.positions[t[1]] - mesh_.positions[t[0]], mesh_.positions[t[2]] - mesh_.positions[t[0]]);
        if (!(glm::length(normal) > 0.0)) continue;
        const Vec3 n = glm::normalize(normal);
        const double r = glm::dot(n, hit.point - at);
        a11 += n.x * n.x;
        a12 += n.x * n.y;
        a22 += n.y * n.y;
        b1 += n.x * r;
        b2 += n.y * r;
      }
      // Damped: a direction no sample's normal sees (a straight wire along itself) stays put.
      const double damping = 1e-3 * (a11 + a22);
      a11 += damping;
      a22 += damping;
      const double det = a11 * a22 - a12 * a12;
      if (!(det > 0.0)) break;
      const glm::dvec2 step((a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det);
      shift += step;
      if (glm::length(step) < 0.01 * tolerance_) break;
    }
    return shift;
  }

  MapScore score(const std::function<glm::dvec2(const glm::dvec2&)>& map) const {
    MapScore s;
    for (const Vec3& p : points_) {
      const glm::dvec2 q = map(glm::dvec2(p));
      if (outside(q)) continue;
      ++s.landed;
      if (bvh_.closest_point(Vec3(q, p.z), tolerance_).face >= 0) ++s.matched;
    }
    return s;
  }

 private:
  // Off the swatch's footprint (its convex outline: a turned swatch's box has bare corners), or
  // within the margin of its edge.
  bool outside(const glm::dvec2& q) const { return !footprint_.contains(q, -margin_); }

  const TriMesh& mesh_;
  FaceBvh bvh_;
  std::vector<Vec3> points_;
  ConvexOutline footprint_;
  double tolerance_ = 0.0, margin_ = 0.0;
};

// The element nearest the middle: every short period maps it onto another element.
size_t middle_element(const CentroidSet& set) {
  size_t best = 0;
  for (size_t i = 1; i < set.shapes().size(); ++i)
    if (glm::distance(set.shapes()[i].centre, set.middle()) < glm::distance(set.shapes()[best].centre, set.middle()))
      best = i;
  return best;
}

std::optional<std::array<glm::dvec2, 2>> find_basis(const CentroidSet& set, size_t middle) {
  const std::vector<ElementShape>& shapes = set.shapes();
  std::vector<glm::dvec2> steps;
  for (const ElementShape& other : shapes)
    if (glm::distance(other.centre, shapes[middle].centre) > set.tolerance() && shapes[middle].matches_turned(other, 0.0))
      steps.push_back(other.centre - shapes[middle].centre);
  std::sort(steps.begin(), steps.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return glm::length(a) < glm::length(b); });
  const int quarter = static_cast<int>(shapes.size() + 3) / 4;
  std::optional<glm::dvec2> first;
  for (const glm::dvec2& step : steps) {
    if (first && std::abs(cross(*first, step)) <= 0.2 * glm::length(*first) * glm::length(step)) continue;
    const MapScore s = set.score([&](const glm::dvec2& p) { return p + step; }, 0.0);
    if (!s.holds() || s.matched < quarter) continue;
    if (!first) {
      first = step;
      continue;
    }
    // The shortest period and the shortest one not parallel to it span a plane lattice.
    return cross(*first, step) > 0.0 ? std::array<glm::dvec2, 2>{*first, step} : std::array<glm::dvec2, 2>{step, *first};
  }
  return std::nullopt;
}

bool on_lattice(const glm::dvec2& p, const std::array<glm::dvec2, 2>& basis, double tolerance) {
  return glm::distance(p, nearest_period(p, basis)) <= tolerance;
}

// The point a turn through `angle` leaves fixed when it sends `from` to `to`:
// (I - R) c = to - R from, invertible for a turn other than the identity.
glm::dvec2 turn_centre(const glm::dvec2& from, const glm::dvec2& to, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double a11 = 1.0 - c, a12 = s, a21 = -s, a22 = 1.0 - c, det = a11 * a22 - a12 * a21;
  const glm::dvec2 r = to - turned(from, angle);
  return {(a22 * r.x - a12 * r.y) / det, (a11 * r.y - a21 * r.x) / det};
}

// Where the centroids show no lattice (yarns): periods among the steps between centroids of
// elements of one kind, and turn centres among the points that turn one element onto another of
// its kind, each checked on the surface.
std::optional<SwatchLattice> surface_lattice(const QuiltSwatch& swatch, const CentroidSet& set, int symmetry) {
  const std::vector<ElementShape>& shapes = set.shapes();
  const SurfaceSamples samples(swatch);
  const auto holds = [&](const MapScore& score) {
    return score.matched >= 0.85 * score.landed && 4 * static_cast<size_t>(score.landed) >= samples.size();
  };
  // A map that puts a fair share of the samples back is refined before it is judged.
  const auto exact_shift = [&](double angle, const glm::dvec2& shift) -> std::optional<glm::dvec2> {
    const auto map = [&](const glm::dvec2& s) { return [&, s](const glm::dvec2& p) { return turned(p, angle) + s; }; };
    const MapScore raw = samples.score(map(shift));
    if (holds(raw)) return shift;
    if (raw.matched < 0.2 * raw.landed) return std::nullopt;
    const glm::dvec2 refined = samples.refined_shift(angle, shift, set.tolerance());
    if (holds(samples.score(map(refined)))) return refined;
    return std::nullopt;
  };
  std::vector<glm::dvec2> steps;
  for (const ElementShape& a : shapes)
    for (const ElementShape& b : shapes) {
      const glm::dvec2 step = b.centre - a.centre;
      if (glm::length(step) <= set.tolerance() || !a.matches_turned(b, 0.0)) continue;
      if (std::none_of(steps.begin(), steps.end(), [&](const glm::dvec2& known) { return glm::distance(known, step) <= set.tolerance(); }))
        steps.push_back(step);
    }
  std::sort(steps.begin(), steps.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return glm::length(a) < glm::length(b); });
  std::optional<glm::dvec2> first;
  std::optional<SwatchLattice> lattice;
  for (const glm::dvec2& centroid_step : steps) {
    if (first && std::abs(cross(*first, centroid_step)) <= 0.2 * glm::length(*first) * glm::length(centroid_step)) continue;
    const std::optional<glm::dvec2> step = exact_shift(0.0, centroid_step);
    if (!step) continue;
    if (!first) {
      first = step;
      continue;
    }
    lattice = SwatchLattice{};
    lattice->basis = cross(*first, *step) > 0.0 ? std::array<glm::dvec2, 2>{*first, *step} : std::array<glm::dvec2, 2>{*step, *first};
    break;
  }
  if (!lattice || symmetry <= 1) return lattice;
  const double angle = 2.0 * kPi / symmetry;
  for (const glm::dvec2& v : lattice->basis)
    if (!on_lattice(turned(v, angle), lattice->basis, set.tolerance())) return std::nullopt;
  int best_matched = -1;
  double best_distance = std::numeric_limits<double>::max();
  std::vector<glm::dvec2> tried;
  for (const ElementShape& a : shapes)
    for (const ElementShape& b : shapes) {
      if (!a.matches_turned(b, angle)) continue;
      const glm::dvec2 centre = turn_centre(a.centre, b.centre, angle);
      if (std::any_of(tried.begin(), tried.end(), [&](const glm::dvec2& c) { return glm::distance(c, centre) <= set.tolerance(); }))
        continue;
      tried.push_back(centre);
      // p -> c + R (p - c) is R p + (c - R c): its shift refined, the centre (I - R)^-1 of it.
      const glm::dvec2 centroid_shift = centre - turned(centre, angle);
      const std::optional<glm::dvec2> shift = exact_shift(angle, centroid_shift);
      if (!shift) continue;
      const glm::dvec2 exact = *shift == centroid_shift ? centre : turn_centre(glm::dvec2(0.0), *shift, angle);
      const MapScore score = samples.score([&](const glm::dvec2& p) { return exact + turned(p - exact, angle); });
      const double distance = glm::distance(exact, set.middle());
      if (score.matched > best_matched || (score.matched == best_matched && distance < best_distance)) {
        best_matched = score.matched;
        best_distance = distance;
        lattice->centre = exact;
      }
    }
  if (best_matched < 0) return std::nullopt;
  return lattice;
}

}  // namespace

glm::dvec2 lattice_coordinates(const glm::dvec2& p, const std::array<glm::dvec2, 2>& basis) {
  const double det = cross(basis[0], basis[1]);
  return {cross(p, basis[1]) / det, cross(basis[0], p) / det};
}

glm::dvec2 nearest_period(const glm::dvec2& p, const std::array<glm::dvec2, 2>& basis) {
  const glm::dvec2 k = lattice_coordinates(p, basis);
  return std::floor(k.x + 0.5 + 1e-7) * basis[0] + std::floor(k.y + 0.5 + 1e-7) * basis[1];
}

std::optional<SwatchLattice> swatch_lattice(const QuiltSwatch& swatch, int symmetry) {
  const CentroidSet set(element_shapes(swatch));
  if (set.shapes().size() < 4 || !(set.tolerance() > 0.0)) return std::nullopt;
  const size_t middle = middle_element(set);
  const std::optional<std::array<glm::dvec2, 2>> basis = find_basis(set, middle);
  if (!basis) return surface_lattice(swatch, set, symmetry);
  SwatchLattice lattice;
  lattice.basis = *basis;
  if (symmetry <= 1) return lattice;
  const double angle = 2.0 * kPi / symmetry;
  for (const glm::dvec2& v : lattice.basis)
    if (!on_lattice(turned(v, angle), lattice.basis, set.tolerance())) return std::nullopt;
  // The turn about c sends the middle element onto some element j of its kind turned, so c is
  // where that turn leaves fixed: p_j = c + R (p_m - c).
  const std::vector<ElementShape>& shapes = set.shapes();
  const glm::dvec2 pm = shapes[middle].centre;
  int best_matched = -1;
  double best_distance = std::numeric_limits<double>::max();
  for (const ElementShape& other : shapes) {
    if (!shapes[middle].matches_turned(other, angle)) continue;
    const glm::dvec2 centre = turn_centre(pm, other.centre, angle);
    const MapScore score = set.score([&](const glm::dvec2& p) { return centre + turned(p - centre, angle); }, angle);
    if (!score.holds()) continue;
    const double distance = glm::distance(centre, set.middle());
    if (score.matched > best_matched || (score.matched == best_matched && distance < best_distance)) {
      best_matched = score.matched;
      best_distance = distance;
      lattice.centre = centre;
    }
  }
  if (best_matched < 0) return std::nullopt;
  return lattice;
}

std::vector<glm::dvec2> lattice_placements(const std::vector<glm::dvec2>& candidates, const glm::dvec2& shift,
                                           const std::array<glm::dvec2, 2>& basis, double slack) {
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (const glm::dvec2& t : candidates) {
    lo = glm::min(lo, t);
    hi = glm::max(hi, t);
  }
  // The box's corners in lattice coordinates bound the periods to try.
  glm::dvec2 k_lo(std::numeric_limits<double>::max()), k_hi(std::numeric_limits<double>::lowest());
  for (const glm::dvec2& c : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)}) {
    const glm::dvec2 k = lattice_coordinates(c + shift, basis);
    k_lo = glm::min(k_lo, k);
    k_hi = glm::max(k_hi, k);
  }
  if ((k_hi.x - k_lo.x + 1.0) * (k_hi.y - k_lo.y + 1.0) > 1e5) return {};
  std::vector<glm::dvec2> placements;
  for (double k1 = std::ceil(k_lo.y); k1 <= k_hi.y; ++k1)
    for (double k0 = std::ceil(k_lo.x); k0 <= k_hi.x; ++k0) {
      const glm::dvec2 t = k0 * basis[0] + k1 * basis[1] - shift;
      if (t.x >= lo.x - slack && t.y >= lo.y - slack && t.x <= hi.x + slack && t.y <= hi.y + slack) placements.push_back(t);
    }
  if (placements.empty()) placements.push_back(nearest_period(0.5 * (lo + hi) + shift, basis) - shift);
  return placements;
}

}  // namespace meshquilt
