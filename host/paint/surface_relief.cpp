#include "paint/surface_relief.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "spatial/face_bvh.h"
#include "surface/surface_types.h"

namespace meshquilt {

ReliefResult relief_surface(const TriMesh& base, const ColourImage& sample,
                            const std::vector<FieldConstraint>& constraints, const ReliefOptions& options) {
  if (!(options.height > 0.0) || !std::isfinite(options.height))
    throw InputError("{height}: expected a positive number of base units", ErrorKind::invalid_option);
  if (!(options.clearance > 0.0 && options.clearance < 1.0))
    throw InputError("{clearance}: expected a share in (0, 1)", ErrorKind::invalid_option);
  const PaintResult painted = paint_surface(base, sample, constraints, options.paint);
  ReliefResult result;
  result.levels = painted.levels;
  result.mesh = painted.mesh;
  const TriMesh& mesh = painted.mesh;
  const BaseSurface surface(mesh);
  const FaceBvh bvh(mesh);
  const size_t n = mesh.num_vertices();
  result.heights.resize(n);
  std::vector<Vec3> moved(n);
  for (size_t v = 0; v < n; ++v) {
    const auto& c = mesh.colors[v];
    const double signal = (0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]) / 255.0;
    double h = options.height * signal;
    const Vec3& p = mesh.positions[v];
    const Vec3& normal = surface.vertex_normals[v];
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
      const double converge = -glm::dot(surface.vertex_normals[w] - normal, e) / (length * length);
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
  return result;
}

}  // namespace meshquilt
