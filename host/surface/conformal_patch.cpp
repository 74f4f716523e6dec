#include "surface/conformal_patch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Sparse>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "numerics/sparse_solve.h"
#include "surface/field_aligned_chart.h"
#include "surface/base_layout.h"
#include "mesh/measures.h"
#include "mesh/topology.h"

namespace meshquilt {
namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// Barycentrics (b1, b2) of p in triangle (a, b, c) of the plane; NaN for a degenerate one.
glm::dvec2 plane_barycentric(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double area = cross2(b - a, c - a);
  if (area == 0.0) return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
  return {cross2(p - a, c - a) / area, cross2(b - a, p - a) / area};
}

// The point of triangle (a, b, c) nearest to p, as barycentrics (b1, b2).
glm::dvec2 clamped_barycentric(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const glm::dvec2 inside = plane_barycentric(p, a, b, c);
  if (std::isfinite(inside.x) && inside.x >= 0.0 && inside.y >= 0.0 && inside.x + inside.y <= 1.0) return inside;
  // Nearest point on each edge; the best of three.
  const glm::dvec2 corners[3] = {a, b, c};
  double best = std::numeric_limits<double>::max();
  glm::dvec2 result(0.0);
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 s = corners[k], e = corners[(k + 1) % 3];
    const double len2 = glm::dot(e - s, e - s);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s, e - s) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec2 q = s + t * (e - s);
    const double d = glm::dot(p - q, p - q);
    if (d >= best) continue;
    best = d;
    double w[3] = {0.0, 0.0, 0.0};
    w[k] = 1.0 - t;
    w[(k + 1) % 3] = t;
    result = {w[1], w[2]};
  }
  return result;
}

// V - E + F of a set of faces: 1 for a disk.
int euler_characteristic(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  std::unordered_set<int32_t> vertices;
  std::unordered_set<uint64_t> edges;
  for (int32_t f : faces) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      vertices.insert(t[k]);
      edges.insert(undirected_edge_key(t[k], t[(k + 1) % 3]));
    }
  }
  return static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) + static_cast<int>(faces.size());
}

// The faces of `ball` reached from `seed_face` across edges, nearest first (by their nearest
// corner's distance), while they stay a disk: a face joins across one edge with a new third
// vertex, or across two (a notch). Returns them sorted.
std::vector<int32_t> disk_within(const BaseSurface& base, const std::vector<int32_t>& ball, int32_t seed_face,
                                 const std::unordered_map<int32_t, double>& distance) {
  const TriMesh& mesh = base.mesh;
  const std::unordered_set<int32_t> in_ball(ball.begin(), ball.end());
  // The face across edge k of f when it is in the ball, else -1.
  const auto across = [&](int32_t f, int k) {
    const int32_t g = base.face_across[f][k];
    return g >= 0 && in_ball.count(g) ? g : -1;
  };
  const auto priority = [&](int32_t f) {
    double d = std::numeric_limits<double>::infinity();
    for (int32_t v : mesh.triangles[f])
      if (const auto it = distance.find(v); it != distance.end()) d = std::min(d, it->second);
    return d;
  };
  std::unordered_set<int32_t> in_disk, disk_vertices;
  std::vector<int32_t> disk;
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  const auto add = [&](int32_t f) {
    in_disk.insert(f);
    disk.push_back(f);
    for (int k = 0; k < 3; ++k) {
      disk_vertices.insert(mesh.triangles[f][k]);
      const int32_t g = across(f, k);
      if (g >= 0 && !in_disk.count(g)) queue.emplace(priority(g), g);
    }
  };
  add(seed_face);
  while (!queue.empty()) {
    const int32_t g = queue.top().second;
    queue.pop();
    if (in_disk.count(g)) continue;
    int shared = 0;
    bool new_vertex = false;
    for (int k = 0; k < 3; ++k) {
      const int32_t h = across(g, k);
      if (h >= 0 && in_disk.count(h)) ++shared;
      if (!disk_vertices.count(mesh.triangles[g][k])) new_vertex = true;
    }
    if ((shared == 1 && new_vertex) || shared == 2) add(g);
  }
  std::sort(disk.begin(), disk.end());
  return disk;
}

}  // namespace

glm::dvec2 SurfacePatch::to_plane(const SurfacePoint& p) const {
  const int32_t f = face_index(p.face);
  const int32_t* v = &local_vertex_of_face_[3 * static_cast<size_t>(f)];
  return (1.0 - p.bary.x - p.bary.y) * uv[v[0]] + p.bary.x * uv[v[1]] + p.bary.y * uv[v[2]];
}

int32_t SurfacePatch::face_index(int32_t base_face) const {
  const auto it = std::lower_bound(sorted_faces_.begin(), sorted_faces_.end(), base_face);
  if (it == sorted_faces_.end() || *it != base_face) return -1;
  return sorted_positions_[it - sorted_faces_.begin()];
}

void SurfacePatch::transform(double angle, double scale) {
  const double c = std::cos(angle) * scale, s = std::sin(angle) * scale;
  for (glm::dvec2& p : uv) p = {c * p.x - s * p.y, s * p.x + c * p.y};
  origin = {c * origin.x - s * origin.y, s * origin.x + c * origin.y};
}

void SurfacePatch::index() {
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (const glm::dvec2& p : uv) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double side = std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
  // About two faces per grid cell.
  const int n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(faces.size()) / 2.0)), 1, 512);
  grid_cell_ = side / n * (1.0 + 1e-9);
  grid_lo_ = lo;
  grid_nx_ = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / grid_cell_)) + 1);
  grid_ny_ = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / grid_cell_)) + 1);
  std::vector<std::vector<int32_t>> cells(static_cast<size_t>(grid_nx_) * grid_ny_);
  for (size_t f = 0; f < faces.size(); ++f) {
    glm::dvec2 a(std::numeric_limits<double>::max()), b(std::numeric_limits<double>::lowest());
    for (int k = 0; k < 3; ++k) {
      a = glm::min(a, uv[local_vertex_of_face_[3 * f + k]]);
      b = glm::max(b, uv[local_vertex_of_face_[3 * f + k]]);
    }
    const int x0 = static_cast<int>((a.x - lo.x) / grid_cell_), x1 = static_cast<int>((b.x - lo.x) / grid_cell_);
    const int y0 = static_cast<int>((a.y - lo.y) / grid_cell_), y1 = static_cast<int>((b.y - lo.y) / grid_cell_);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells[static_cast<size_t>(y) * grid_nx_ + x].push_back(static_cast<int32_t>(f));
  }
  grid_offsets_.assign(1, 0);
  grid_faces_.clear();
  for (const auto& cell : cells) {
    grid_faces_.insert(grid_faces_.end(), cell.begin(), cell.end());
    grid_offsets_.push_back(static_cast<int32_t>(grid_faces_.size()));
  }
}

std::optional<SurfacePoint> SurfacePatch::locate(const glm::dvec2& p) const {
  const double gx = (p.x - grid_lo_.x) / grid_cell_, gy = (p.y - grid_lo_.y) / grid_cell_;
  if (!(gx >= 0.0 && gy >= 0.0 && gx < grid_nx_ && gy < grid_ny_)) return std::nullopt;
  const size_t cell = static_cast<size_t>(gy) * grid_nx_ + static_cast<size_t>(gx);
  constexpr double kSlack = 1e-12;
  for (int32_t k = grid_offsets_[cell]; k < grid_offsets_[cell + 1]; ++k) {
    const int32_t f = grid_faces_[k];
    const int32_t* v = &local_vertex_of_face_[3 * static_cast<size_t>(f)];
    const glm::dvec2 b = plane_barycentric(p, uv[v[0]], uv[v[1]], uv[v[2]]);
    if (b.x >= -kSlack && b.y >= -kSlack && b.x + b.y <= 1.0 + kSlack)
      return SurfacePoint{faces[f], glm::clamp(b, 0.0, 1.0)};
  }
  return std::nullopt;
}

SurfacePoint SurfacePatch::nearest(const glm::dvec2& p) const {
  double best = std::numeric_limits<double>::max();
  SurfacePoint result;
  for (size_t f = 0; f < faces.size(); ++f) {
    const int32_t* v = &local_vertex_of_face_[3 * f];
    const glm::dvec2 b = clamped_barycentric(p, uv[v[0]], uv[v[1]], uv[v[2]]);
    const glm::dvec2 q = (1.0 - b.x - b.y) * uv[v[0]] + b.x * uv[v[1]] + b.y * uv[v[2]];
    const double d = glm::dot(p - q, p - q);
    if (d < best) {
      best = d;
      result = {faces[f], b};
    }
  }
  return result;
}

std::vector<glm::dvec2> conformal_flattening(const BaseSurface& base, const std::vector<int32_t>& faces,
                                             const std::vector<int32_t>& corner_vertex,
                                             const std::vector<int32_t>& vertex_base) {
  const TriMesh& mesh = base.mesh;
  const int32_t n = static_cast<int32_t>(vertex_base.size());
  // LSCM: per face, grad v = rot90(grad u), two rows weighted by sqrt(area), in the face's own
  // orthonormal frame (x along its first edge, normal out of the surface).
  const int32_t pin_a = corner_vertex[0];
  int32_t pin_b = corner_vertex[1];
  {
    double far = -1.0;
    for (int32_t k = 0; k < n; ++k) {
      const double d = glm::distance(mesh.positions[vertex_base[k]], mesh.positions[vertex_base[pin_a]]);
      if (d > far) {
        far = d;
        pin_b = k;
      }
    }
  }
  // Unknown index of (vertex, coordinate); pinned ones map to -1.
  std::vector<int32_t> column(2 * static_cast<size_t>(n), -1);
  int32_t unknowns = 0;
  for (int32_t k = 0; k < n; ++k)
    if (k != pin_a && k != pin_b) {
      column[k] = unknowns++;
      column[n + k] = unknowns++;
    }
  const double pinned_value[4] = {0.0, 0.0, 1.0, 0.0};  // u_a, v_a, u_b, v_b
  const auto pinned = [&](int32_t index) -> double {
    const int32_t k = index % n, coordinate = index / n;
    return pinned_value[(k == pin_a ? 0 : 2) + coordinate];
  };
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> rhs;
  int32_t row = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const Tri& t = mesh.triangles[faces[f]];
    const Vec3 p0 = mesh.positions[t[0]], p1 = mesh.positions[t[1]], p2 = mesh.positions[t[2]];
    const double area = base.face_areas[faces[f]];
    if (area <= 0.0) continue;
    const Vec3 e1 = glm::normalize(p1 - p0);
    const Vec3 e2 = glm::normalize(glm::cross(glm::cross(p1 - p0, p2 - p0), e1));
    const glm::dvec2 q[3] = {glm::dvec2(0.0), glm::dvec2(glm::length(p1 - p0), 0.0),
                             glm::dvec2(glm::dot(p2 - p0, e1), glm::dot(p2 - p0, e2))};
    const double weight = std::sqrt(area);
    double row_rhs[2] = {0.0, 0.0};
    for (int k = 0; k < 3; ++k) {
      // Gradient of the k-th hat function: rot90(q[k+2] - q[k+1]) / (2 area).
      const glm::dvec2 edge = q[(k + 2) % 3] - q[(k + 1) % 3];
      const glm::dvec2 g = glm::dvec2(-edge.y, edge.x) / (2.0 * area) * weight;
      const int32_t vertex = corner_vertex[3 * f + k];
      // Row 0: dv/dx + du/dy = 0; row 1: dv/dy - du/dx = 0.
      const double coefficient[2][2] = {{g.y, g.x}, {-g.x, g.y}};  // [row][u or v]
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
          const int32_t index = c * n + vertex;
          if (column[index] >= 0)
            triplets.emplace_back(row + r, column[index], coefficient[r][c]);
          else
            row_rhs[r] -= coefficient[r][c] * pinned(index);
        }
    }
    rhs.push_back(row_rhs[0]);
    rhs.push_back(row_rhs[1]);
    row += 2;
  }
  std::vector<double> solution(static_cast<size_t>(unknowns), 0.0);
  if (unknowns > 0) {
    Eigen::SparseMatrix<double> A(row, unknowns);
    A.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), static_cast<Eigen::Index>(rhs.size()));
    const Eigen::SparseMatrix<double> normal = A.transpose() * A;
    const Eigen::MatrixXd x = solve_positive_definite(normal, A.transpose() * b, "conformal map");
    for (int32_t k = 0; k < unknowns; ++k) solution[k] = x(k, 0);
  }
  std::vector<glm::dvec2> uv(static_cast<size_t>(n));
  for (int32_t k = 0; k < n; ++k) {
    for (int c = 0; c < 2; ++c) {
      const int32_t index = c * n + k;
      uv[k][c] = column[index] >= 0 ? solution[column[index]] : pinned(index);
    }
  }

  return uv;
}

namespace {

// Fold-overs and the spread of plane area / base area over the patch's faces (faces of
// negligible area left out), for uv scaled by `scale`.
void measure_distortion(const BaseSurface& base, SurfacePatch& patch, double scale) {
  double base_area = 0.0;
  for (int32_t f : patch.faces) base_area += base.face_areas[f];
  double lo = std::numeric_limits<double>::max(), hi = 0.0;
  patch.flipped_faces = 0;
  for (size_t f = 0; f < patch.faces.size(); ++f) {
    const int32_t* v = &patch.local_vertex_of_face_[3 * f];
    const double signed_area = 0.5 * cross2(patch.uv[v[1]] - patch.uv[v[0]], patch.uv[v[2]] - patch.uv[v[0]]);
    const double area = base.face_areas[patch.faces[f]];
    if (area <= 1e-12 * base_area) continue;
    const double ratio = signed_area * scale * scale / area;
    if (ratio <= 0.0) {
      ++patch.flipped_faces;
      continue;
    }
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  patch.area_distortion = hi > 0.0 && lo < std::numeric_limits<double>::max() ? hi / lo : 1.0;
}

// Plane positions from a window's corners; corners of one vertex that unfold to different places
// (round a cone of the layout) become separate vertices, so the patch is slit there.
void slit_open(SurfacePatch& patch, const std::vector<glm::dvec2>& corner_uv, double tolerance) {
  std::vector<std::vector<int32_t>> copies(patch.vertices.size());  // vertex -> its plane copies
  patch.uv.assign(patch.vertices.size(), glm::dvec2(0.0));
  for (size_t corner = 0; corner < corner_uv.size(); ++corner) {
    int32_t& vertex = patch.local_vertex_of_face_[corner];
    const glm::dvec2 p = corner_uv[corner];
    auto& known = copies[vertex];
    const auto same = std::find_if(known.begin(), known.end(),
                                   [&](int32_t copy) { return glm::length(patch.uv[copy] - p) <= tolerance; });
    if (same != known.end()) {
      vertex = *same;
      continue;
    }
    int32_t copy = vertex;
    if (!known.empty()) {
      copy = static_cast<int32_t>(patch.vertices.size());
      patch.vertices.push_back(patch.vertices[vertex]);
      patch.uv.emplace_back(0.0);
    }
    patch.uv[copy] = p;
    known.push_back(copy);
    vertex = copy;
  }
}

// Whether two plane triangles' interiors overlap by more than `slack` (separating axes).
bool triangles_overlap(const std::array<glm::dvec2, 3>& a, const std::array<glm::dvec2, 3>& b, double slack) {
  for (const auto* tri : {&a, &b})
    for (int e = 0; e < 3; ++e) {
      const glm::dvec2 d = (*tri)[(e + 1) % 3] - (*tri)[e];
      const glm::dvec2 axis(-d.y, d.x);
      const double len = glm::length(axis);
      if (!(len > 0.0)) continue;
      double alo = 1e300, ahi = -1e300, blo = 1e300, bhi = -1e300;
      for (const glm::dvec2& p : a) { const double x = glm::dot(p, axis) / len; alo = std::min(alo, x); ahi = std::max(ahi, x); }
      for (const glm::dvec2& p : b) { const double x = glm::dot(p, axis) / len; blo = std::min(blo, x); bhi = std::max(bhi, x); }
      if (ahi <= blo + slack || bhi <= alo + slack) return false;
    }
  return true;
}

// The faces of the patch whose plane image overlaps that of a face nearer to `origin` in space
// (sharing no base vertex with it), taken nearest first: round a cone of negative index, or over
// a fold of the base, a window wraps over itself, and a point there would stand for two places.
// Nearest first keeps a whole disk slit where the two sheets meet; dropping the farther of each
// overlapping pair would also drop faces whose partner was itself dropped, and hole both sheets.
std::vector<uint8_t> overlapping_faces(const SurfacePatch& patch, const TriMesh& mesh, const Vec3& origin) {
  const size_t n = patch.faces.size();
  std::vector<uint8_t> result(n, 0);
  if (n == 0) return result;
  std::vector<std::array<glm::dvec2, 3>> tri(n);
  std::vector<glm::dvec2> box_lo(n), box_hi(n);
  std::vector<std::pair<double, int32_t>> order(n);
  glm::dvec2 lo(1e300), hi(-1e300);
  double edge = 0.0;
  for (size_t f = 0; f < n; ++f) {
    const Tri& t = mesh.triangles[patch.faces[f]];
    for (int c = 0; c < 3; ++c) tri[f][c] = patch.uv[patch.local_vertex_of_face_[3 * f + c]];
    box_lo[f] = glm::min(glm::min(tri[f][0], tri[f][1]), tri[f][2]);
    box_hi[f] = glm::max(glm::max(tri[f][0], tri[f][1]), tri[f][2]);
    lo = glm::min(lo, box_lo[f]);
    hi = glm::max(hi, box_hi[f]);
    edge += glm::length(tri[f][1] - tri[f][0]);
    const Vec3 centre = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
    order[f] = {glm::distance(origin, centre), static_cast<int32_t>(f)};
  }
  std::sort(order.begin(), order.end());
  edge = std::max(edge / n, 1e-300);
  const double cell = 2.0 * edge;
  const int nx = std::max(1, std::min(1024, static_cast<int>((hi.x - lo.x) / cell) + 1));
  const int ny = std::max(1, std::min(1024, static_cast<int>((hi.y - lo.y) / cell) + 1));
  const auto column = [&](double x) { return std::clamp(static_cast<int>((x - lo.x) / cell), 0, nx - 1); };
  const auto row = [&](double y) { return std::clamp(static_cast<int>((y - lo.y) / cell), 0, ny - 1); };
  // Faces kept so far, by grid cell.
  std::vector<std::vector<int32_t>> grid(static_cast<size_t>(nx) * ny);
  for (const auto& [distance, f] : order) {
    const Tri& tf = mesh.triangles[patch.faces[f]];
    const int x0 = column(box_lo[f].x), x1 = column(box_hi[f].x), y0 = row(box_lo[f].y), y1 = row(box_hi[f].y);
    bool covered = false;
    for (int y = y0; y <= y1 && !covered; ++y)
      for (int x = x0; x <= x1 && !covered; ++x)
        for (int32_t g : grid[static_cast<size_t>(y) * nx + x]) {
          const glm::dvec2 lo_both = glm::max(box_lo[f], box_lo[g]), hi_both = glm::min(box_hi[f], box_hi[g]);
          if (lo_both.x >= hi_both.x || lo_both.y >= hi_both.y) continue;
          const Tri& tg = mesh.triangles[patch.faces[g]];
          bool shared = false;
          for (int32_t v : tf) shared = shared || v == tg[0] || v == tg[1] || v == tg[2];
          if (shared || !triangles_overlap(tri[f], tri[g], 1e-3 * edge)) continue;
          covered = true;
          break;
        }
    if (covered) {
      result[f] = 1;
      continue;
    }
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) grid[static_cast<size_t>(y) * nx + x].push_back(f);
  }
  return result;
}

// The faces of `faces` (sorted) reached from `start` across edges between them, sorted.
std::vector<int32_t> connected_within(const BaseSurface& base, const std::vector<int32_t>& faces, int32_t start) {
  std::unordered_set<int32_t> left(faces.begin(), faces.end());
  std::vector<int32_t> result{start};
  left.erase(start);
  for (size_t next = 0; next < result.size(); ++next)
    for (int32_t g : base.face_across[result[next]])
      if (g >= 0 && left.erase(g) > 0) result.push_back(g);
  std::sort(result.begin(), result.end());
  return result;
}

// The patch over `faces` (sorted), with its local vertices; no plane yet.
void set_faces(const TriMesh& mesh, SurfacePatch& patch, const std::vector<int32_t>& faces) {
  patch.faces = faces;
  patch.vertices.clear();
  patch.local_vertex_of_face_.clear();
  std::unordered_map<int32_t, int32_t> local;
  for (int32_t f : faces)
    for (int32_t v : mesh.triangles[f])
      if (local.emplace(v, static_cast<int32_t>(patch.vertices.size())).second) patch.vertices.push_back(v);
  patch.local_vertex_of_face_.reserve(3 * faces.size());
  for (int32_t f : faces)
    for (int32_t v : mesh.triangles[f]) patch.local_vertex_of_face_.push_back(local[v]);
  patch.sorted_faces_ = faces;
  patch.sorted_positions_.resize(faces.size());
  for (size_t k = 0; k < faces.size(); ++k) patch.sorted_positions_[k] = static_cast<int32_t>(k);
}

// The patch moved so that the seed is the plane's origin.
SurfacePatch& centred(SurfacePatch& patch, const SurfacePoint& seed) {
  const glm::dvec2 seed_plane = patch.to_plane(seed);
  for (glm::dvec2& p : patch.uv) p -= seed_plane;
  patch.origin = seed_plane;
  return patch;
}

}  // namespace

std::vector<int32_t> ball_faces(const BaseSurface& base, const SurfacePoint& seed, double radius) {
  const TriMesh& mesh = base.mesh;
  // Dijkstra along edges from the seed face's corners.
  std::unordered_map<int32_t, double> distance;
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  const Vec3 origin = base.position(seed);
  for (int32_t v : mesh.triangles[seed.face]) {
    const double d = glm::distance(origin, mesh.positions[v]);
    auto [it, fresh] = distance.emplace(v, d);
    if (fresh || d < it->second) it->second = d;
    queue.emplace(d, v);
  }
  std::vector<int32_t> reached;
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    reached.push_back(v);
    for (const auto& [w, length] : base.edges[v]) {
      const double dw = d + length;
      if (dw > radius) continue;
      auto [it, fresh] = distance.emplace(w, dw);
      if (!fresh && dw >= it->second) continue;
      it->second = dw;
      queue.emplace(dw, w);
    }
  }
  std::vector<int32_t> faces{seed.face};
  for (int32_t v : reached)
    for (int32_t f : base.vertex_faces[v]) faces.push_back(f);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  // Degenerate faces carry no conformal information and would make rows of zeros.
  faces.erase(std::remove_if(faces.begin(), faces.end(),
                             [&](int32_t f) { return f != seed.face && base.face_areas[f] <= 0.0; }),
              faces.end());
  // A ball that wraps around a handle or a thin part, or covers a closed component, is no disk,
  // and a conformal map of it folds (36 of 60 full-size balls on genus-4 fertility at
  // `--scale 0.13` were none): it is cut open where its fronts meet.
  if (euler_characteristic(mesh, faces) != 1) faces = disk_within(base, faces, seed.face, distance);
  return faces;
}

namespace {

// The window of the shared layout over `faces`, less the faces it folds round a cone and the
// farther of two it lays over each other (a point over them goes to the nearest face), rather
// than give up the shared layout for the whole patch; nullopt where it still folds.
std::optional<SurfacePatch> window_of(const BaseSurface& base, const SurfacePoint& seed, double radius,
                                      const std::vector<int32_t>& faces, const BaseLayout& layout) {
  const TriMesh& mesh = base.mesh;
  const Vec3 origin = base.position(seed);
  // Where the layout folds the seed's own face, the window starts from the nearest face it
  // does not: a window needs its start face.
  SurfacePoint anchor = seed;
  const auto window_over = [&](const std::vector<int32_t>& window_faces) {
    SurfacePatch window;
    window.radius = radius;
    set_faces(mesh, window, window_faces);
    const LayoutWindow unfolded = layout.unfold(window_faces, anchor.face, window.local_vertex_of_face_,
                                                static_cast<int32_t>(window.vertices.size()));
    slit_open(window, unfolded.corner_uv, 1e-6 * radius);
    measure_distortion(base, window, 1.0);
    return window;
  };
  SurfacePatch slit = window_over(faces);
  // Unfolded without the faces left out, a window may reach round the cone the other way.
  const int most = std::max<int>(1, static_cast<int>(faces.size()) / 50);
  for (int round = 0; round < 4 && slit.flipped_faces <= most; ++round) {
    std::vector<uint8_t> left_out(slit.faces.size(), 0);
    if (slit.flipped_faces > 0) {
      for (size_t k = 0; k < slit.faces.size(); ++k) {
        const int32_t* v = &slit.local_vertex_of_face_[3 * k];
        left_out[k] = cross2(slit.uv[v[1]] - slit.uv[v[0]], slit.uv[v[2]] - slit.uv[v[0]]) <= 0.0;
      }
      const size_t at = static_cast<size_t>(slit.face_index(anchor.face));
      if (left_out[at]) {
        double nearest = std::numeric_limits<double>::max();
        for (size_t k = 0; k < slit.faces.size(); ++k) {
          const double d = glm::distance(origin, base.position({slit.faces[k], glm::dvec2(1.0 / 3.0)}));
          if (left_out[k] || d >= nearest) continue;
          nearest = d;
          anchor = {slit.faces[k], glm::dvec2(1.0 / 3.0)};
        }
        if (anchor.face == seed.face) break;
      }
    } else {
      left_out = overlapping_faces(slit, mesh, origin);
    }
    std::vector<int32_t> kept_faces;
    for (size_t k = 0; k < slit.faces.size(); ++k)
      if (!left_out[k] || slit.faces[k] == anchor.face) kept_faces.push_back(slit.faces[k]);
    if (kept_faces.size() == slit.faces.size()) break;
    slit = window_over(connected_within(base, kept_faces, anchor.face));
  }
  if (slit.flipped_faces > 0) return std::nullopt;
  // The layout's scale changes over a window as it does over every window round it: a smaller
  // window would change nothing.
  slit.area_distortion = 1.0;
  slit.chart = PatchChart::layout_window;
  return std::move(centred(slit, anchor));
}

}  // namespace

std::optional<SurfacePatch> grow_layout_window(const BaseSurface& base, const SurfacePoint& seed, double radius,
                                               const BaseLayout& layout) {
  return window_of(base, seed, radius, ball_faces(base, seed, radius), layout);
}

SurfacePatch grow_conformal_patch(const BaseSurface& base, const SurfacePoint& seed, double radius,
                                  const std::vector<Vec3>* face_field, const BaseLayout* layout, bool layout_window) {
  const TriMesh& mesh = base.mesh;
  SurfacePatch patch;
  patch.radius = radius;
  const std::vector<int32_t> faces = ball_faces(base, seed, radius);
  set_faces(mesh, patch, faces);

  // A window of the shared layout where it unfolds without a cone or a fold; a field-aligned
  // chart of the patch alone (the layout's field, combed over the window) where that does not
  // fold; the conformal map, scaled to the patch's area, otherwise and where no layout is given.
  if (layout) {
    if (layout_window)
      if (std::optional<SurfacePatch> window = window_of(base, seed, radius, faces, *layout)) return std::move(*window);
    const LayoutWindow window =
        layout->unfold(faces, seed.face, patch.local_vertex_of_face_, static_cast<int32_t>(patch.vertices.size()));
    std::vector<Vec3> face_field(mesh.num_faces(), Vec3(0.0));
    for (size_t k = 0; k < faces.size(); ++k) {
      Vec3 d = layout->axis(faces[k]);
      for (int q = 0; q < (4 / layout->symmetry()) * window.face_turn[k]; ++q) d = glm::cross(base.face_normals[faces[k]], d);
      face_field[faces[k]] = d;
    }
    patch.uv = field_aligned_flattening(base, faces, patch.local_vertex_of_face_, patch.vertices, face_field);
    measure_distortion(base, patch, 1.0);
    if (patch.flipped_faces == 0) {
      patch.chart = PatchChart::field_aligned;
      return centred(patch, seed);
    }
    patch.flipped_faces = 0;
  } else if (face_field) {
    patch.uv = field_aligned_flattening(base, faces, patch.local_vertex_of_face_, patch.vertices, *face_field);
    measure_distortion(base, patch, 1.0);
    if (patch.flipped_faces == 0) {
      patch.chart = PatchChart::field_aligned;
      return centred(patch, seed);
    }
    patch.flipped_faces = 0;
  }
  patch.uv = conformal_flattening(base, faces, patch.local_vertex_of_face_, patch.vertices);
  // Scaled to the base's area.
  double plane_area = 0.0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const int32_t* v = &patch.local_vertex_of_face_[3 * f];
    plane_area += 0.5 * cross2(patch.uv[v[1]] - patch.uv[v[0]], patch.uv[v[2]] - patch.uv[v[0]]);
  }
  double base_area = 0.0;
  for (int32_t f : faces) base_area += base.face_areas[f];
  const double scale = plane_area > 0.0 ? std::sqrt(base_area / plane_area) : 1.0;
  measure_distortion(base, patch, scale);
  for (glm::dvec2& p : patch.uv) p *= scale;
  return centred(patch, seed);
}

}  // namespace meshquilt
