#include "paint/surface_relief.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "spatial/face_bvh.h"
#include "spatial/intersecting_pairs.h"
#include "surface/surface_types.h"

namespace meshquilt {
namespace {

// Halvings of the heights of faces that cross before they go to 0 (2^-11 of a height: below any
// fold's depth).
constexpr int kCrossingRounds = 12;

// The share of a vertex's height its neighbours' mean takes: a half cancels a zigzag a pixel wide.
constexpr double kNeighbourShare = 0.5;

// Passes that bring a turned face's highest corner to its lowest before whole faces go to the base.
constexpr int kUnfoldPasses = 32;

// The base's smooth normal at each vertex of its split: the base's vertex normals interpolated
// over the base face the vertex lies in. The split's own normals are the base faces' inside each
// face and turn at once across its edges, where a raised sheet would fold on itself.
std::vector<Vec3> smooth_normals(const TriMesh& base, const TriMesh& split, int levels) {
  const BaseSurface surface(base);
  std::vector<Vec3> out(split.num_vertices(), Vec3(0.0));
  std::vector<uint8_t> done(split.num_vertices(), 0);
  for (size_t g = 0; g < split.num_faces(); ++g) {
    const Tri& t = base.triangles[g >> (2 * levels)];
    const Vec3 a = base.positions[t[0]], e1 = base.positions[t[1]] - a, e2 = base.positions[t[2]] - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double det = d11 * d22 - d12 * d12;
    for (int32_t v : split.triangles[g]) {
      if (done[v]) continue;
      done[v] = 1;
      const Vec3 q = split.positions[v] - a;
      const double p1 = glm::dot(q, e1), p2 = glm::dot(q, e2);
      const double s = det > 0.0 ? (d22 * p1 - d12 * p2) / det : 0.0, r = det > 0.0 ? (d11 * p2 - d12 * p1) / det : 0.0;
      const Vec3 n = (1.0 - s - r) * surface.vertex_normals[t[0]] + s * surface.vertex_normals[t[1]] +
                     r * surface.vertex_normals[t[2]];
      out[v] = glm::length(n) > 1e-12 ? glm::normalize(n) : surface.face_normals[g >> (2 * levels)];
    }
  }
  return out;
}

// Faces turned over by the raise, against the base's own face normals. A face turns where a
// steep step in the heights meets normals that lean across it: the crossing test, which skips
// faces that share a vertex, does not see such a fold.
std::vector<size_t> turned_faces(const TriMesh& raised, const BaseSurface& base) {
  std::vector<size_t> out;
  for (size_t f = 0; f < raised.num_faces(); ++f) {
    const Tri& t = raised.triangles[f];
    const Vec3* p = raised.positions.data();
    if (glm::dot(glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]), base.face_normals[f]) < 0.0) out.push_back(f);
  }
  return out;
}

// The synthesized signal (the vertex colours' luma), each vertex's own and its neighbours' mean
// weighed by kNeighbourShare: where two patches of the sample meet, vertices a pixel apart may
// alternate between them, and raised that zigzag becomes a row of teeth.
std::vector<double> smoothed_at_the_pixel(const TriMesh& mesh, const BaseSurface& surface) {
  const size_t n = mesh.num_vertices();
  std::vector<double> signal(n), out(n);
  for (size_t v = 0; v < n; ++v) {
    const auto& c = mesh.colors[v];
    signal[v] = luma(glm::dvec3(c[0], c[1], c[2])) / 255.0;
  }
  for (size_t v = 0; v < n; ++v) {
    out[v] = signal[v];
    if (surface.edges[v].empty()) continue;
    double mean = 0.0;
    for (const auto& [u, length] : surface.edges[v]) mean += signal[u];
    mean /= static_cast<double>(surface.edges[v].size());
    out[v] = (1.0 - kNeighbourShare) * signal[v] + kNeighbourShare * mean;
  }
  return out;
}

}  // namespace

ReliefResult relief_surface(const TriMesh& base, const ColourImage& sample,
                            const std::vector<FieldConstraint>& constraints, const ReliefOptions& options,
                            engine::Device& device) {
  if (!(options.height > 0.0) || !std::isfinite(options.height))
    throw InputError("{height}: expected a positive number of base units", ErrorKind::invalid_option);
  if (!(options.clearance > 0.0 && options.clearance < 1.0))
    throw InputError("{clearance}: expected a share in (0, 1)", ErrorKind::invalid_option);
  const PaintResult painted = paint_surface(base, sample, constraints, options.paint, device);
  ReliefResult result;
  result.levels = painted.levels;
  result.mesh = painted.mesh;
  result.directions = painted.directions;
  const TriMesh& mesh = painted.mesh;
  const BaseSurface surface(mesh);
  const std::vector<Vec3> normals = smooth_normals(base, mesh, painted.levels);
  const FaceBvh bvh(mesh);
  const size_t n = mesh.num_vertices();
  result.heights.resize(n);
  std::vector<Vec3> moved(n);
  const std::vector<double> signal = smoothed_at_the_pixel(mesh, surface);
  for (size_t v = 0; v < n; ++v) {
    double h = options.height * signal[v];
    const Vec3& p = mesh.positions[v];
    const Vec3& normal = normals[v];
    // Room along the normal: the surface the ray meets, past the vertex's own faces.
    double room = std::numeric_limits<double>::infinity();
    double nearest_edge = std::numeric_limits<double>::infinity();
    for (const auto& [w, length] : surface.edges[v]) nearest_edge = std::min(nearest_edge, length);
    const double start = 1e-3 * nearest_edge;
    const RayHit hit = bvh.ray_cast(p + start * normal, normal);
    if (hit.face >= 0) room = hit.distance + start;
    // Where neighbouring normals converge (concave), at about the radius of curvature.
    for (const auto& [w, length] : surface.edges[v]) {
      const Vec3 e = mesh.positions[w] - p;
      const double converge = -glm::dot(normals[w] - normal, e) / (length * length);
      if (converge > 0.0) room = std::min(room, 1.0 / converge);
    }
    if (h > options.clearance * room) {
      h = options.clearance * room;
      ++result.clamped;
    }
    result.heights[v] = h;
    moved[v] = p + h * normal;
  }
  result.mesh.positions = std::move(moved);
  // Those clamps look at one vertex at a time: across a crease, or a fold of a scan, raised
  // neighbours may still cross, and at a steep step a face may turn over. Such heights come
  // down until no face is turned and no two cross (the base itself, at height 0, is the last
  // resort).
  const std::vector<int32_t> one_element(mesh.num_faces(), 0);
  std::vector<uint8_t> lowered(n, 0);
  const auto lower_to = [&](int32_t v, double level) {
    if (result.heights[v] <= level) return;
    result.heights[v] = level;
    result.mesh.positions[v] = mesh.positions[v] + level * normals[v];
    if (!lowered[v]) {
      lowered[v] = 1;
      ++result.lowered_crossing;
    }
  };
  for (int round = 0;; ++round) {
    // Each turned face's highest corner comes down to its lowest until none is turned; after
    // kUnfoldPasses, whole turned faces go to the base. Heights only fall, so it ends.
    for (int pass = 0;; ++pass) {
      const std::vector<size_t> turned = turned_faces(result.mesh, surface);
      if (turned.empty()) break;
      for (size_t f : turned) {
        Tri t = mesh.triangles[f];
        std::sort(t.begin(), t.end(), [&](int32_t a, int32_t b) { return result.heights[a] > result.heights[b]; });
        if (pass < kUnfoldPasses)
          lower_to(t[0], result.heights[t[2]]);
        else
          for (int32_t v : t) lower_to(v, 0.0);
      }
    }
    const std::vector<FacePair> crossing =
        intersecting_face_pairs(result.mesh, one_element, IntersectionScope::same_element);
    if (crossing.empty()) break;
    if (round == kCrossingRounds) {  // at height 0 and still crossing: the base crosses itself
      result.crossing_left = crossing.size();
      break;
    }
    std::vector<uint8_t> lower(n, 0);
    for (const auto& [f, g] : crossing)
      for (int32_t v : {mesh.triangles[f][0], mesh.triangles[f][1], mesh.triangles[f][2], mesh.triangles[g][0],
                        mesh.triangles[g][1], mesh.triangles[g][2]})
        lower[v] = 1;
    for (size_t v = 0; v < n; ++v)
      if (lower[v]) lower_to(static_cast<int32_t>(v), round + 1 < kCrossingRounds ? 0.5 * result.heights[v] : 0.0);
  }
  return result;
}

}  // namespace meshquilt
