#include "mesh/base_mesh.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"

namespace meshquilt {
namespace {

// A part lying farther from the largest part than this many of its diagonals is a stray.
constexpr double kStrayPartDistance = 10.0;

// Refuses a base with a part far away from its largest part (an exporter's stray face): the
// scale, relative to the bounding box, would make the texture too large for the base.
void refuse_stray_parts(const TriMesh& mesh, const std::string& source) {
  int32_t count = 0;
  const std::vector<int32_t> part = face_components(mesh, &count);
  if (count < 2) return;
  std::vector<Box3> boxes(count);
  std::vector<int64_t> faces(count, 0);
  std::vector<int32_t> first_face(count, -1);
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    Box3& box = boxes[part[f]];
    for (int32_t v : mesh.triangles[f]) {
      const Vec3& p = mesh.positions[v];
      box.lo = glm::min(box.lo, p);
      box.hi = glm::max(box.hi, p);
    }
    if (first_face[part[f]] < 0) first_face[part[f]] = static_cast<int32_t>(f);
    ++faces[part[f]];
  }
  const int32_t largest = static_cast<int32_t>(std::max_element(faces.begin(), faces.end()) - faces.begin());
  const double size = glm::length(boxes[largest].extent());
  for (int32_t c = 0; c < count; ++c) {
    const Vec3 gap = glm::max(glm::max(boxes[largest].lo - boxes[c].hi, boxes[c].lo - boxes[largest].hi), Vec3(0.0));
    if (glm::length(gap) <= kStrayPartDistance * size) continue;
    char text[320];
    const Vec3& p = mesh.positions[mesh.triangles[first_face[c]][0]];
    std::snprintf(text, sizeof text,
                  ": a part of %lld face(s) (first at (%.3g, %.3g, %.3g)) lies %.3g away from the largest part, "
                  "%.3g x its size: delete the stray part or quilt the parts one by one",
                  static_cast<long long>(faces[c]), p.x, p.y, p.z, glm::length(gap), glm::length(gap) / size);
    throw InputError(source + text);
  }
}

}  // namespace

TriMesh prepare_base(const TriMesh& input, const std::string& source, MeshRepairs* repairs) {
  RepairedMesh repaired = repair_mesh(input, source, kWeldTolerance);
  if (repairs) *repairs = repaired.repairs;
  TriMesh& mesh = repaired.mesh;
  mesh.elements.clear();
  mesh.origins.clear();  // the base's own numbering is the one that counts from here
  double total_area = 0.0;
  for (const Tri& t : mesh.triangles)
    total_area += glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                         mesh.positions[t[2]] - mesh.positions[t[0]]));
  const double diagonal = glm::length(bounding_box(mesh.positions).extent());
  if (!(total_area > 1e-12 * diagonal * diagonal))
    throw InputError(source + ": no face has area (each has its corners on a line)");
  refuse_stray_parts(mesh, source);
  return mesh;
}

std::vector<int32_t> prepared_vertex_sources(const TriMesh& mesh) {
  TriMesh numbered = mesh;
  numbered.origins.resize(mesh.positions.size());
  std::iota(numbered.origins.begin(), numbered.origins.end(), 0);
  return repair_mesh(numbered, "base", kWeldTolerance).mesh.origins;
}

TriMesh posed_base(const TriMesh& prepared, const std::vector<int32_t>& sources, const TriMesh& frame) {
  TriMesh posed = prepared;
  for (size_t v = 0; v < sources.size(); ++v) posed.positions[v] = frame.positions[sources[v]];
  return posed;
}

}  // namespace meshquilt
