#include "mesh/swatch_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "mesh/validation.h"

namespace meshquilt {

void check_swatch_proportions(const TriMesh& swatch, const std::string& source) {
  auto fail = [&](const std::string& problem) {
    throw InputError(source + ": degenerate swatch: " + problem, ErrorKind::invalid_mesh);
  };
  auto vertex_text = [&](size_t v) {
    char buffer[160];
    const Vec3& p = swatch.positions[v];
    // Named as the file numbers it: a repaired swatch carries its file's order in origins.
    const size_t named = swatch.origins.size() == swatch.positions.size() ? swatch.origins[v] : v;
    std::snprintf(buffer, sizeof(buffer), "vertex %zu at (%.3g, %.3g, %.3g)", named, p.x, p.y, p.z);
    return std::string(buffer);
  };
  // Float kernels square coordinates measured in edge lengths; beyond this nothing is a swatch.
  for (size_t v = 0; v < swatch.positions.size(); ++v) {
    const Vec3& p = swatch.positions[v];
    if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxSwatchCoordinate) {
      fail(vertex_text(v) + " lies beyond +-1e15");
    }
  }
  const Box3 box = bounding_box(swatch.positions);
  const Vec3 extent = box.extent();
  const int height = thinnest_axis(extent);
  const double wide = std::max(extent[(height + 1) % 3], extent[(height + 2) % 3]);
  const double narrow = std::min(extent[(height + 1) % 3], extent[(height + 2) % 3]);
  // A stray vertex far from the rest: the bounding box is then many orders of magnitude larger
  // than the faces. A closed layer of F faces with edges e spans about sqrt(F) e, so compare the
  // diagonal with the median edge length, with a generous margin for uneven meshes.
  std::vector<double> edges;
  edges.reserve(swatch.triangles.size() * 3);
  for (const Tri& t : swatch.triangles) {
    for (int k = 0; k < 3; ++k) edges.push_back(glm::distance(swatch.positions[t[k]], swatch.positions[t[(k + 1) % 3]]));
  }
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  const double median_edge = edges[edges.size() / 2];
  const double diagonal = glm::length(extent);
  const double allowed = kStrayVertexFactor * std::sqrt(static_cast<double>(swatch.triangles.size()));
  if (!(diagonal <= allowed * median_edge)) {
    // Name the vertex farthest from the coordinate-wise median point: the likely stray one.
    Vec3 median;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      values.reserve(swatch.positions.size());
      for (const Vec3& p : swatch.positions) values.push_back(p[axis]);
      std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
      median[axis] = values[values.size() / 2];
    }
    size_t far = 0;
    double far_distance = -1.0;
    for (size_t v = 0; v < swatch.positions.size(); ++v) {
      const double d = glm::distance(swatch.positions[v], median);
      if (d > far_distance) {
        far_distance = d;
        far = v;
      }
    }
    char buffer[200];
    std::snprintf(buffer, sizeof(buffer), "bounding box %.3g across is %.3g median edge lengths for %zu faces (at most %.3g); ",
                  diagonal, median_edge > 0.0 ? diagonal / median_edge : HUGE_VAL, swatch.triangles.size(), allowed);
    fail(buffer + vertex_text(far) + " lies far from the rest");
  }
  // The grid has cells_across_swatch cells along the shorter side, so an aspect of A means
  // 16 A cells along the longer one per swatch extent: a sliver would ask for billions.
  if (narrow > 0.0 && !(wide <= kMaxSwatchAspect * narrow)) {  // zero: orient_swatch says so
    char buffer[200];
    std::snprintf(buffer, sizeof(buffer), "x-y extents %.3g x %.3g, an aspect of %.3g (at most %g)", wide, narrow,
                  wide / narrow, kMaxSwatchAspect);
    fail(buffer);
  }
}

int thinnest_axis(const Vec3& extent) {
  if (extent.z <= extent.x && extent.z <= extent.y) return 2;
  return extent.x <= extent.y ? 0 : 1;
}

TriMesh orient_swatch(const TriMesh& input, const std::string& source, MeshRepairs* repairs) {
  RepairedMesh repaired = repair_mesh(input, source, kWeldTolerance);
  if (repairs) *repairs = repaired.repairs;
  const TriMesh& swatch = repaired.mesh;
  // First: a stray vertex also spoils the thickness test below, whose message would mislead.
  check_swatch_proportions(swatch, source);
  const Box3 box = bounding_box(swatch.positions);
  const Vec3 low = box.lo, extent = box.extent();
  const double diagonal = glm::length(extent);
  const int height = thinnest_axis(extent);
  // A cyclic permutation (x,y,z) -> (y,z,x) or (z,x,y) has determinant +1; a swap of two axes
  // would mirror the swatch and flip every triangle.
  const int axis_x = (height + 1) % 3;
  const int axis_y = (height + 2) % 3;
  auto fail = [&](const std::string& problem) {
    throw InputError(source + ": degenerate swatch: " + problem, ErrorKind::invalid_mesh);
  };
  if (!(extent[height] >= 1e-9 * diagonal) || !(diagonal > 0.0)) {
    fail("zero thickness (height " + std::to_string(extent[height]) + ", bounding-box diagonal " +
         std::to_string(diagonal) + ")");
  }
  if (!(extent[axis_x] > 0.0) || !(extent[axis_y] > 0.0)) fail("zero extent in the x-y plane");

  TriMesh out = std::move(repaired.mesh);
  for (Vec3& p : out.positions) {
    const Vec3 q = p - low;
    p = Vec3(q[axis_x], q[axis_y], q[height]);
  }
  return out;
}

}  // namespace meshquilt
