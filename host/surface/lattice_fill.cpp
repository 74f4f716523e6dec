#include "surface/lattice_fill.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

namespace meshquilt {

std::vector<double> distance_to_breaks(const BaseSurface& base,
                                       const std::vector<std::pair<int32_t, Vec3>>& points) {
  const TriMesh& mesh = base.mesh;
  std::vector<double> reached(mesh.num_vertices(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> front;
  const auto start = [&](int32_t v, double d) {
    if (d < reached[v]) {
      reached[v] = d;
      front.push({d, v});
    }
  };
  for (const auto& [f, p] : points)
    for (int32_t v : mesh.triangles[f]) start(v, glm::distance(mesh.positions[v], p));
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int32_t across : base.face_across[f])
      if (across < 0)
        for (int32_t v : mesh.triangles[f]) start(v, 0.0);
  while (!front.empty()) {
    const auto [d, v] = front.top();
    front.pop();
    if (d > reached[v]) continue;
    for (const auto& [w, length] : base.edges[v])
      if (d + length < reached[w]) {
        reached[w] = d + length;
        front.push({reached[w], w});
      }
  }
  return reached;
}

bool FilledWindow::covers(const glm::dvec2& p, double margin, const std::vector<uint8_t>& kept) const {
  const auto near = [&](const Rect2& r) { return Rect2{r.lo - margin, r.hi + margin}.contains(p); };
  bool over = false;
  for (const auto& [r, e] : present) {
    if (!kept[e] && near(r)) return false;
    over = over || (kept[e] && r.contains(p));
  }
  return over && std::none_of(absent.begin(), absent.end(), near);
}

size_t LatticeFill::KeyHash::operator()(const Key& k) const {
  return static_cast<size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
}

LatticeFill::LatticeFill(const BaseSurface& base, const QuiltSwatch& swatch, const SwatchLattice& lattice,
                         std::vector<LatticeClass> classes, std::vector<double> break_distance, double margin,
                         double unit, double height_unit)
    : base_(base),
      swatch_(swatch),
      lattice_(lattice),
      classes_(std::move(classes)),
      break_distance_(std::move(break_distance)),
      margin_(margin),
      unit_(unit),
      height_unit_(height_unit),
      // Two elements of the pattern lie far more than a tenth of an edge apart; rounding, far less.
      bucket_(0.1 * swatch.mean_edge * unit) {
  for (const LatticeClass& c : classes_) {
    const TriMesh& element = swatch_.elements[c.element];
    double z = 0.0;
    for (const Vec3& p : element.positions) z += p.z;
    class_height_.push_back(element.positions.empty() ? 0.0
                                                      : z / static_cast<double>(element.positions.size()));
    class_bounds_.push_back(swatch_.element_bounds[c.element]);
  }
}

bool LatticeFill::any() const {
  return std::any_of(classes_.begin(), classes_.end(), [](const LatticeClass& c) { return c.alone; });
}

bool LatticeFill::near_break(const SurfacePoint& p) const {
  const Tri& t = base_.mesh.triangles[p.face];
  const double d = (1.0 - p.bary.x - p.bary.y) * break_distance_[t[0]] + p.bary.x * break_distance_[t[1]] +
                   p.bary.y * break_distance_[t[2]];
  return !(d >= margin_);
}

int32_t LatticeFill::placed_before(const Vec3& centre) const {
  const Key k{static_cast<int64_t>(std::floor(centre.x / bucket_)),
              static_cast<int64_t>(std::floor(centre.y / bucket_)),
              static_cast<int64_t>(std::floor(centre.z / bucket_))};
  for (int64_t dz = -1; dz <= 1; ++dz)
    for (int64_t dy = -1; dy <= 1; ++dy)
      for (int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = placed_.find({k.x + dx, k.y + dy, k.z + dz});
        if (it == placed_.end()) continue;
        for (const auto& [c, e] : it->second)
          if (glm::distance(c, centre) <= bucket_) return e;
      }
  return -1;
}

FilledWindow LatticeFill::fill(const SurfacePatch& window, const glm::dvec2& shift) {
  FilledWindow out;
  Rect2 box{glm::dvec2(std::numeric_limits<double>::max()),
            glm::dvec2(std::numeric_limits<double>::lowest())};
  for (const glm::dvec2& p : window.uv) {
    box.lo = glm::min(box.lo, p);
    box.hi = glm::max(box.hi, p);
  }
  struct Candidate {
    int32_t cls;
    glm::dvec2 t;
    Vec3 centre;
    std::vector<LocalVertex> vertices;
    bool whole = false;
  };
  std::vector<Candidate> candidates;
  const std::array<glm::dvec2, 2>& basis = lattice_.basis;
  for (size_t a = 0; a < classes_.size(); ++a) {
    const LatticeClass& cls = classes_[a];
    const Rect2& b = class_bounds_[a];
    // Centroids c + P - shift whose element's bounds meet the window's box.
    const glm::dvec2 lo = box.lo - (b.hi - cls.centroid) - cls.centroid + shift;
    const glm::dvec2 hi = box.hi - (b.lo - cls.centroid) - cls.centroid + shift;
    glm::dvec2 k_lo(std::numeric_limits<double>::max()), k_hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec2& c : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)}) {
      const glm::dvec2 k = lattice_coordinates(c, basis);
      k_lo = glm::min(k_lo, k);
      k_hi = glm::max(k_hi, k);
    }
    if ((k_hi.x - k_lo.x + 1.0) * (k_hi.y - k_lo.y + 1.0) > 1e6) return {};
    for (double ky = std::ceil(k_lo.y); ky <= k_hi.y; ++ky)
      for (double kx = std::ceil(k_lo.x); kx <= k_hi.x; ++kx) {
        const glm::dvec2 t = kx * basis[0] + ky * basis[1] - shift;
        const Rect2 bounds{b.lo + t, b.hi + t};
        if (!bounds.overlaps(box)) continue;
        const std::optional<SurfacePoint> at = cls.alone ? window.locate(cls.centroid + t) : std::nullopt;
        if (!at || near_break(*at)) {
          out.absent.push_back(bounds);
          continue;
        }
        const Vec3 centre = base_.position(*at) + base_.normal(*at) * (class_height_[a] * height_unit_);
        if (const int32_t e = placed_before(centre); e >= 0) {
          out.present.emplace_back(bounds, e);
          continue;
        }
        candidates.push_back({static_cast<int32_t>(a), t, centre, {}, false});
      }
  }
  // Each candidate's vertices are its own to place.
  tbb::parallel_for(size_t{0}, candidates.size(), [&](size_t c) {
    Candidate& candidate = candidates[c];
    const TriMesh& element = swatch_.elements[classes_[candidate.cls].element];
    candidate.vertices.reserve(element.positions.size());
    for (const Vec3& p : element.positions) {
      const std::optional<SurfacePoint> at = window.locate(glm::dvec2(p) + candidate.t);
      if (!at || near_break(*at)) return;
      candidate.vertices.push_back({*at, p.z * height_unit_});
    }
    // A window cut open beside a cone puts faces from its two sides next to each other: an
    // element across that cut would land in two places.
    for (const Tri& f : element.triangles)
      for (int k = 0; k < 3; ++k) {
        const int32_t u = f[k], v = f[(k + 1) % 3];
        const double plane =
            glm::distance(glm::dvec2(element.positions[u]), glm::dvec2(element.positions[v])) * unit_;
        const double base = glm::distance(base_.position(candidate.vertices[u].point),
                                          base_.position(candidate.vertices[v].point));
        if (base > 4.0 * plane + bucket_) return;
      }
    candidate.whole = true;
  });
  for (Candidate& candidate : candidates) {
    const Rect2& b = class_bounds_[candidate.cls];
    const Rect2 bounds{b.lo + candidate.t, b.hi + candidate.t};
    if (!candidate.whole) {
      out.absent.push_back(bounds);
      continue;
    }
    const Vec3& c = candidate.centre;
    placed_[{static_cast<int64_t>(std::floor(c.x / bucket_)), static_cast<int64_t>(std::floor(c.y / bucket_)),
             static_cast<int64_t>(std::floor(c.z / bucket_))}]
        .emplace_back(c, filled_);
    out.present.emplace_back(bounds, filled_);
    out.added.push_back({classes_[candidate.cls].element, std::move(candidate.vertices)});
    ++filled_;
  }
  return out;
}

}  // namespace meshquilt
