#include "inspect/coverage.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <tuple>
#include <limits>
#include <string>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/error.h"
#include "spatial/box_grid.h"
#include "mesh/convex_outline.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

struct Box2 {
  double x0, y0, x1, y1;
};

// Closed triangle (projected to x-y) against a closed box: separating axes of the box and the
// triangle's edge normals. Also right for triangles whose projection is a segment or a point.
bool triangle_overlaps_box(const glm::dvec2 p[3], const Box2& box) {
  for (int i = 0; i < 3; ++i) {
    const glm::dvec2 e = p[(i + 1) % 3] - p[i];
    const glm::dvec2 n(-e.y, e.x);
    if (n.x == 0.0 && n.y == 0.0) continue;
    double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
    for (int k = 0; k < 3; ++k) {
      const double t = glm::dot(n, p[k]);
      tmin = std::min(tmin, t);
      tmax = std::max(tmax, t);
    }
    const glm::dvec2 corners[4] = {{box.x0, box.y0}, {box.x1, box.y0}, {box.x0, box.y1}, {box.x1, box.y1}};
    double bmin = std::numeric_limits<double>::infinity(), bmax = -bmin;
    for (const auto& c : corners) {
      const double t = glm::dot(n, c);
      bmin = std::min(bmin, t);
      bmax = std::max(bmax, t);
    }
    if (tmax < bmin || bmax < tmin) return false;
  }
  return true;  // the box axes were checked by the caller's cell range
}

// Cells of the nx x ny grid tiling [lo, hi] that the x-y projection of some triangle overlaps
// (closed sets), row by row.
std::vector<char> covered_cells(const TriMesh& mesh, const glm::dvec2& lo, const glm::dvec2& hi, int32_t nx,
                                int32_t ny) {
  const double cw = (hi.x - lo.x) / nx, ch = (hi.y - lo.y) / ny;
  const int64_t total = static_cast<int64_t>(nx) * ny;
  std::vector<std::atomic<char>> marks(total);  // written concurrently by the face loop

  auto cell_range = [](double a, double b, double origin, double step, int32_t n) {
    // Closed cells: a value on a shared border touches both cells.
    int64_t i0 = step > 0 ? static_cast<int64_t>(std::floor((a - origin) / step)) : 0;
    int64_t i1 = step > 0 ? static_cast<int64_t>(std::floor((b - origin) / step)) : n - 1;
    if (step > 0 && a - origin == double(i0) * step) --i0;
    return std::pair<int64_t, int64_t>(std::max<int64_t>(i0, 0), std::min<int64_t>(i1, n - 1));
  };
  // Faces only ever set marks, so relaxed atomic stores suffice.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.num_faces(), 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t f = r.begin(); f < r.end(); ++f) {
      const Tri& t = mesh.triangles[f];
      const glm::dvec2 p[3] = {glm::dvec2(mesh.positions[t[0]]), glm::dvec2(mesh.positions[t[1]]), glm::dvec2(mesh.positions[t[2]])};
      const glm::dvec2 tlo = glm::min(p[0], glm::min(p[1], p[2])), thi = glm::max(p[0], glm::max(p[1], p[2]));
      if (thi.x < lo.x || thi.y < lo.y || tlo.x > hi.x || tlo.y > hi.y) continue;
      const auto [ix0, ix1] = cell_range(tlo.x, thi.x, lo.x, cw, nx);
      const auto [iy0, iy1] = cell_range(tlo.y, thi.y, lo.y, ch, ny);
      for (int64_t iy = iy0; iy <= iy1; ++iy) {
        for (int64_t ix = ix0; ix <= ix1; ++ix) {
          std::atomic<char>& c = marks[iy * nx + ix];
          if (c.load(std::memory_order_relaxed)) continue;
          const Box2 box{lo.x + ix * cw, lo.y + iy * ch, lo.x + (ix + 1) * cw, lo.y + (iy + 1) * ch};
          if (triangle_overlaps_box(p, box)) c.store(1, std::memory_order_relaxed);
        }
      }
    }
  });

  std::vector<char> covered(total);
  for (int64_t i = 0; i < total; ++i) covered[i] = marks[i].load(std::memory_order_relaxed);
  return covered;
}

}  // namespace

PlaneCoverage plane_coverage(const TriMesh& mesh, double cell_size, const PlaneCoverageOptions& options) {
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
    throw InputError("plane coverage: cell size " + std::to_string(cell_size) + " is not positive", ErrorKind::invalid_option);
  }
  if (options.region) {
    const auto& [a, b] = *options.region;
    if (!(b.x > a.x && b.y > a.y) || !std::isfinite(a.x + a.y + b.x + b.y))
      throw InputError("plane coverage: the region is empty or not finite", ErrorKind::invalid_option);
  }
  PlaneCoverage out;
  if (mesh.num_faces() == 0) return out;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  if (options.region) {
    std::tie(lo, hi) = *options.region;
  } else {
    for (const Tri& t : mesh.triangles) {
      for (int32_t v : t) {
        lo = glm::min(lo, glm::dvec2(mesh.positions[v]));
        hi = glm::max(hi, glm::dvec2(mesh.positions[v]));
      }
    }
    const glm::dvec2 size = hi - lo;
    lo += options.margin * size;
    hi -= options.margin * size;
  }
  const glm::dvec2 inner = glm::max(hi - lo, glm::dvec2(0.0));
  auto cells_along = [&](double length, double cell) {
    return static_cast<int64_t>(std::max(1.0, std::round(length / cell)));
  };
  while (cells_along(inner.x, cell_size) * cells_along(inner.y, cell_size) > options.max_cells) cell_size *= 1.5;
  out.cells_x = static_cast<int32_t>(cells_along(inner.x, cell_size));
  out.cells_y = static_cast<int32_t>(cells_along(inner.y, cell_size));
  out.cell_size = cell_size;
  const int64_t total = static_cast<int64_t>(out.cells_x) * out.cells_y;
  const std::vector<char> covered = covered_cells(mesh, lo, lo + inner, out.cells_x, out.cells_y);
  int64_t count = 0;
  for (int64_t i = 0; i < total; ++i) count += covered[i];
  out.coverage = static_cast<double>(count) / static_cast<double>(total);

  // Largest gap: flood fill of uncovered cells (4-connected).
  std::vector<char> seen(total, 0);
  std::vector<int64_t> stack;
  int64_t largest = 0;
  for (int64_t start = 0; start < total; ++start) {
    if (covered[start] || seen[start]) continue;
    int64_t size_of_gap = 0;
    stack.push_back(start);
    seen[start] = 1;
    while (!stack.empty()) {
      const int64_t c = stack.back();
      stack.pop_back();
      ++size_of_gap;
      const int64_t x = c % out.cells_x, y = c / out.cells_x;
      const int64_t next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (const auto& n : next) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= out.cells_x || n[1] >= out.cells_y) continue;
        const int64_t k = n[1] * out.cells_x + n[0];
        if (!covered[k] && !seen[k]) {
          seen[k] = 1;
          stack.push_back(k);
        }
      }
    }
    largest = std::max(largest, size_of_gap);
  }
  out.largest_gap = static_cast<double>(largest) / static_cast<double>(total);
  return out;
}

namespace {

double bbox_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

uint64_t edge_key(int32_t a, int32_t b) {
  const auto x = static_cast<uint32_t>(std::min(a, b)), y = static_cast<uint32_t>(std::max(a, b));
  return (static_cast<uint64_t>(x) << 32) | y;
}

// Angle-weighted pseudo normals of a mesh's faces, edges and vertices.
struct PseudoNormals {
  std::vector<Vec3> face;
  std::vector<Vec3> vertex;
  std::unordered_map<uint64_t, Vec3> edge;

  explicit PseudoNormals(const TriMesh& m) : face(m.num_faces()), vertex(m.num_vertices(), Vec3(0.0)) {
    edge.reserve(2 * m.num_faces());
    for (size_t f = 0; f < m.num_faces(); ++f) {
      const Tri& t = m.triangles[f];
      const Vec3 n = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
      const double len = glm::length(n);
      face[f] = len > 0.0 ? n / len : Vec3(0.0);
      for (int i = 0; i < 3; ++i) {
        const Vec3 e1 = m.positions[t[(i + 1) % 3]] - m.positions[t[i]];
        const Vec3 e2 = m.positions[t[(i + 2) % 3]] - m.positions[t[i]];
        const double l1 = glm::length(e1), l2 = glm::length(e2);
        if (l1 > 0.0 && l2 > 0.0) {
          vertex[t[i]] += std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0, 1.0)) * face[f];
        }
        edge[edge_key(t[i], t[(i + 1) % 3])] += face[f];
      }
    }
  }

  // The normal of the feature the closest point lies on, read from its barycentrics (the
  // closest-point routine returns exact zeros outside the face's interior region).
  Vec3 at(const TriMesh& m, const ClosestPoint& cp) const {
    const Tri& t = m.triangles[cp.face];
    const Vec3& b = cp.barycentric;
    const int zeros = (b.x == 0.0) + (b.y == 0.0) + (b.z == 0.0);
    if (zeros == 2) return vertex[t[b.x != 0.0 ? 0 : (b.y != 0.0 ? 1 : 2)]];
    if (zeros == 1) {
      const int opposite = b.x == 0.0 ? 0 : (b.y == 0.0 ? 1 : 2);
      const auto it = edge.find(edge_key(t[(opposite + 1) % 3], t[(opposite + 2) % 3]));
      if (it != edge.end()) return it->second;
    }
    return face[cp.face];
  }
};

// Van der Corput radical inverse in base 2 and 3, for stratified samples inside a face.
double radical_inverse(uint32_t i, uint32_t base) {
  double inv = 1.0 / base, f = inv, r = 0.0;
  while (i > 0) {
    r += f * (i % base);
    i /= base;
    f *= inv;
  }
  return r;
}

}  // namespace

namespace {

// Heights as in signed_heights; `feet` receives the closest base points.
std::vector<double> heights_and_feet(const std::vector<Vec3>& points, const TriMesh& base, std::vector<Vec3>& feet) {
  if (base.num_faces() == 0) throw InputError("base mesh has no faces");
  const double diagonal = bbox_diagonal(base.positions);
  const double scale = diagonal > 0.0 ? 1.0 / diagonal : 1.0;
  const FaceBvh bvh(base);
  const PseudoNormals normals(base);
  std::vector<double> heights(points.size());
  feet.resize(points.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      const ClosestPoint cp = bvh.closest_point(points[i]);
      feet[i] = cp.point;
      const double side = glm::dot(points[i] - cp.point, normals.at(base, cp));
      heights[i] = (side < 0.0 ? -cp.distance : cp.distance) * scale;
    }
  });
  return heights;
}

}  // namespace

std::vector<double> signed_heights(const std::vector<Vec3>& points, const TriMesh& base) {
  std::vector<Vec3> feet;
  return heights_and_feet(points, base, feet);
}

BaseCoverage base_coverage(const TriMesh& mesh, const TriMesh& base, double radius, const BaseCoverageOptions& options) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw InputError("base coverage: radius " + std::to_string(radius) + " is not positive", ErrorKind::invalid_option);
  }
  if (base.num_faces() == 0) throw InputError("base mesh has no faces");
  BaseCoverage out;
  out.radius = radius;

  // Vertices used by faces only: welded meshes have no others, but do not count strays.
  std::vector<char> used(mesh.num_vertices(), 0);
  for (const Tri& t : mesh.triangles)
    for (int32_t v : t) used[v] = 1;
  std::vector<Vec3> points;
  for (size_t v = 0; v < mesh.num_vertices(); ++v)
    if (used[v]) points.push_back(mesh.positions[v]);

  std::vector<Vec3> all_feet;
  const std::vector<double> heights = heights_and_feet(points, base, all_feet);
  if (!heights.empty()) {
    const auto [mn, mx] = std::minmax_element(heights.begin(), heights.end());
    out.height_min = *mn;
    out.height_max = *mx;
  }
  const double top = options.shell_height.value_or(std::numeric_limits<double>::infinity());
  if (options.shell_height) {
    int64_t outside = 0;
    for (double h : heights) outside += (h < -options.below_tolerance || h > top + options.below_tolerance);
    out.outside_shell_vertices = outside;
  }

  // Feet (closest base points) of the vertices inside the shell, in a hash grid of radius-sized
  // cells, so each sample looks at its 27 neighbouring cells.
  std::vector<Vec3> feet;
  for (size_t i = 0; i < points.size(); ++i) {
    if (heights[i] >= -options.below_tolerance && heights[i] <= top + options.below_tolerance) feet.push_back(all_feet[i]);
  }
  Vec3 origin(std::numeric_limits<double>::infinity());
  for (const Vec3& p : base.positions) origin = glm::min(origin, p);
  auto cell_of = [&](const Vec3& p) { return glm::i64vec3(glm::floor((p - origin) / radius)); };
  auto key_of = [](const glm::i64vec3& c) { return grid_cell_hash(c.x, c.y, c.z); };
  std::unordered_multimap<uint64_t, int32_t> grid;
  grid.reserve(feet.size());
  for (size_t i = 0; i < feet.size(); ++i) grid.emplace(key_of(cell_of(feet[i])), static_cast<int32_t>(i));

  // Samples: per face, a count proportional to its area (at least one), stratified by a
  // Halton sequence mapped uniformly into the triangle.
  double total_area = 0.0;
  std::vector<double> area(base.num_faces());
  for (size_t f = 0; f < base.num_faces(); ++f) {
    const Tri& t = base.triangles[f];
    area[f] = 0.5 * glm::length(glm::cross(base.positions[t[1]] - base.positions[t[0]], base.positions[t[2]] - base.positions[t[0]]));
    total_area += area[f];
  }
  if (!(total_area > 0.0)) return out;
  const double radius2 = radius * radius;
  std::vector<double> covered_area(base.num_faces(), 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, base.num_faces(), 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t f = r.begin(); f < r.end(); ++f) {
      if (area[f] <= 0.0) continue;
      const auto n = static_cast<uint32_t>(std::max(1.0, std::round(area[f] / total_area * double(options.samples))));
      const Tri& t = base.triangles[f];
      const Vec3 &a = base.positions[t[0]], &b = base.positions[t[1]], &c = base.positions[t[2]];
      uint32_t hits = 0;
      for (uint32_t s = 0; s < n; ++s) {
        const double u = radical_inverse(s + 1, 2), v = radical_inverse(s + 1, 3);
        const double su = std::sqrt(u);
        const Vec3 x = (1.0 - su) * a + su * (1.0 - v) * b + su * v * c;
        const glm::i64vec3 cell = cell_of(x);
        bool hit = false;
        for (int dx = -1; dx <= 1 && !hit; ++dx) {
          for (int dy = -1; dy <= 1 && !hit; ++dy) {
            for (int dz = -1; dz <= 1 && !hit; ++dz) {
              const glm::i64vec3 nb = cell + glm::i64vec3(dx, dy, dz);
              const auto range = grid.equal_range(key_of(nb));
              for (auto it = range.first; it != range.second; ++it) {
                const Vec3 d = feet[it->second] - x;
                if (glm::dot(d, d) <= radius2) {
                  hit = true;
                  break;
                }
              }
            }
          }
        }
        hits += hit;
      }
      covered_area[f] = area[f] * hits / n;
    }
  });
  double covered = 0.0;
  for (double a : covered_area) covered += a;
  out.coverage = std::min(1.0, covered / total_area);
  return out;
}

double largest_empty_square(const TriMesh& swatch, int resolution) {
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  std::vector<Vec3> used;
  for (const Tri& t : swatch.triangles)
    for (int32_t v : t) {
      lo = glm::min(lo, glm::dvec2(swatch.positions[v]));
      hi = glm::max(hi, glm::dvec2(swatch.positions[v]));
      used.push_back(swatch.positions[v]);
    }
  const double side = std::max(hi.x - lo.x, hi.y - lo.y);
  if (used.empty() || !(side > 0.0) || resolution < 1) return 0.0;
  const double h = side / resolution;
  const auto nx = static_cast<int32_t>(std::max(1.0, std::ceil((hi.x - lo.x) / h)));
  const auto ny = static_cast<int32_t>(std::max(1.0, std::ceil((hi.y - lo.y) / h)));
  const std::vector<char> covered = covered_cells(swatch, lo, lo + h * glm::dvec2(nx, ny), nx, ny);
  const ConvexOutline outline(used);
  // Chessboard distance of each free pixel to the nearest pixel with geometry or outside the
  // outline (the raster's outside counts as such), in two passes.
  std::vector<int32_t> d(covered.size());
  for (int32_t y = 0; y < ny; ++y)
    for (int32_t x = 0; x < nx; ++x) {
      const glm::dvec2 centre = lo + h * glm::dvec2(x + 0.5, y + 0.5);
      d[static_cast<size_t>(y) * nx + x] = covered[static_cast<size_t>(y) * nx + x] || !outline.contains(centre) ? 0 : 1 << 30;
    }
  const auto at = [&](int32_t x, int32_t y) { return x < 0 || y < 0 || x >= nx || y >= ny ? 0 : d[static_cast<size_t>(y) * nx + x]; };
  for (int32_t y = 0; y < ny; ++y)
    for (int32_t x = 0; x < nx; ++x) {
      int32_t& v = d[static_cast<size_t>(y) * nx + x];
      if (v) v = std::min({v, at(x - 1, y) + 1, at(x - 1, y - 1) + 1, at(x, y - 1) + 1, at(x + 1, y - 1) + 1});
    }
  int32_t largest = 0;
  for (int32_t y = ny - 1; y >= 0; --y)
    for (int32_t x = nx - 1; x >= 0; --x) {
      int32_t& v = d[static_cast<size_t>(y) * nx + x];
      if (v) v = std::min({v, at(x + 1, y) + 1, at(x + 1, y + 1) + 1, at(x, y + 1) + 1, at(x - 1, y + 1) + 1});
      largest = std::max(largest, v);
    }
  // The widest free run holds at most 2d free pixels (d its largest distance), and a free
  // square may reach into the partly covered pixel on either side of it.
  return (2.0 * largest + 2.0) * h;
}

double self_covering_cell(const TriMesh& swatch, double swatch_length) {
  for (int n = 64; n >= 1; --n) {
    const double cell = swatch_length / n;
    // At four phases of the grid (the margin moves its origin by quarter cells), so that a
    // sparse swatch does not pass only because its wires happen to fall into every cell.
    bool covers = true;
    for (int k = 0; k < 4 && covers; ++k) {
      PlaneCoverageOptions shifted;
      shifted.margin = 0.02 + k * cell / (4.0 * swatch_length);
      covers = plane_coverage(swatch, cell, shifted).coverage >= 1.0;
    }
    if (covers) return cell;
  }
  return swatch_length;
}

TriMesh plane_body(const TriMesh& mesh) {
  std::vector<Vec3> centroid;
  for (const auto& t : mesh.triangles)
    centroid.push_back((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0);
  auto percentile = [&](int axis, double q) {
    std::vector<double> v;
    for (const Vec3& c : centroid) v.push_back(c[axis]);
    const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * v.size()));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[k];
  };
  const Vec3 lo(percentile(0, 0.02), percentile(1, 0.02), 0.0), hi(percentile(0, 0.98), percentile(1, 0.98), 0.0);
  TriMesh body;
  body.positions = mesh.positions;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Vec3& c = centroid[f];
    if (c.x >= lo.x && c.x <= hi.x && c.y >= lo.y && c.y <= hi.y) body.triangles.push_back(mesh.triangles[f]);
  }
  const double tiny = 1e-6 * (hi.x - lo.x);
  for (const Vec3& corner : {lo, hi}) {
    const auto base = static_cast<int32_t>(body.positions.size());
    body.positions.insert(body.positions.end(), {corner, corner + Vec3(tiny, 0, 0), corner + Vec3(0, tiny, 0)});
    body.triangles.push_back({base, base + 1, base + 2});
  }
  // Unused vertices outside the box would still widen the bounding box.
  std::vector<Vec3> kept;
  std::vector<int32_t> index(body.positions.size(), -1);
  for (auto& t : body.triangles)
    for (int32_t& v : t) {
      if (index[v] < 0) index[v] = static_cast<int32_t>(kept.size()), kept.push_back(body.positions[v]);
      v = index[v];
    }
  body.positions = kept;
  body.elements.assign(body.triangles.size(), 0);
  return body;
}

}  // namespace meshquilt
