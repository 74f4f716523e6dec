#include "surface/disc_chart.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "mesh/topology.h"

namespace meshquilt {

DiscChart disc_chart(const BaseSurface& base, const std::string& name) {
  const SurfaceReport report = inspect_surface(base.mesh);
  // A disc: one piece whose Euler characteristic is 1 (V - E + F), so one boundary and no handle.
  if (report.components != 1 || report.boundary_edges == 0 || report.euler != 1)
    throw InputError(name + ": a design drapes over a disc (one piece, one boundary, no handle); this base has " +
                         std::to_string(report.components) + " piece(s), " + std::to_string(report.boundary_edges) +
                         " boundary edges and Euler characteristic " + std::to_string(report.euler) +
                         " (cut a closed base open along a seam first)",
                     ErrorKind::invalid_option);
  // Seed at the face nearest the area centroid; a radius past the diagonal takes every face.
  Vec3 centroid(0.0);
  for (size_t f = 0; f < base.mesh.num_faces(); ++f) {
    const Tri& t = base.mesh.triangles[f];
    centroid += base.face_areas[f] / base.area *
                (base.mesh.positions[t[0]] + base.mesh.positions[t[1]] + base.mesh.positions[t[2]]) / 3.0;
  }
  int32_t seed = 0;
  double nearest = 1e300;
  for (size_t f = 0; f < base.mesh.num_faces(); ++f) {
    const Tri& t = base.mesh.triangles[f];
    const Vec3 middle = (base.mesh.positions[t[0]] + base.mesh.positions[t[1]] + base.mesh.positions[t[2]]) / 3.0;
    const double d = glm::dot(middle - centroid, middle - centroid);
    if (base.face_areas[f] > 0.0 && d < nearest) {
      nearest = d;
      seed = static_cast<int32_t>(f);
    }
  }
  DiscChart chart;
  chart.patch = grow_conformal_patch(base, SurfacePoint{seed, glm::dvec2(1.0 / 3.0)}, 4.0 * base.diagonal);
  chart.area_distortion = chart.patch.area_distortion;
  // Centre at the chart's area centroid and turn its longer principal axis onto y.
  SurfacePatch& patch = chart.patch;
  glm::dvec2 mean(0.0);
  double total = 0.0;
  std::vector<glm::dvec2> middles;
  std::vector<double> areas;
  for (const int32_t f : patch.faces) {
    const glm::dvec2 a = patch.to_plane({f, glm::dvec2(0.0, 0.0)}), b = patch.to_plane({f, glm::dvec2(1.0, 0.0)}),
                     c = patch.to_plane({f, glm::dvec2(0.0, 1.0)});
    const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    middles.push_back((a + b + c) / 3.0);
    areas.push_back(area);
    mean += area * middles.back();
    total += area;
  }
  mean /= total;
  double xx = 0.0, yy = 0.0, xy = 0.0;
  for (size_t k = 0; k < middles.size(); ++k) {
    const glm::dvec2 d = middles[k] - mean;
    xx += areas[k] * d.x * d.x;
    yy += areas[k] * d.y * d.y;
    xy += areas[k] * d.x * d.y;
  }
  const double major = 0.5 * std::atan2(2.0 * xy, xx - yy);  // the longer axis's angle from x
  for (glm::dvec2& p : patch.uv) p -= mean;
  patch.origin -= mean;
  patch.transform(0.5 * kPi - major, 1.0);
  patch.index();
  return chart;
}

}  // namespace meshquilt
