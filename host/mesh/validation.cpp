#include "mesh/validation.h"

#include <cmath>

#include "core/error.h"

namespace meshquilt {

void validate_mesh(const TriMesh& mesh, const std::string& source) {
  auto fail = [&](const std::string& problem) { throw InputError(source + ": " + problem, ErrorKind::invalid_mesh); };
  if (mesh.triangles.empty()) fail("mesh has no faces");
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      fail("vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
    }
  }
  // Compare as unsigned so a negative index is caught by the same test as a too-large one.
  const auto num_vertices = static_cast<uint64_t>(mesh.positions.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int32_t index : mesh.triangles[f]) {
      if (index < 0 || static_cast<uint64_t>(index) >= num_vertices) {
        fail("face " + std::to_string(f) + " has vertex index " + std::to_string(index) + " outside [0, " +
             std::to_string(num_vertices) + ")");
      }
    }
  }
  if (!mesh.elements.empty()) {
    if (mesh.elements.size() != mesh.triangles.size()) {
      fail(std::to_string(mesh.elements.size()) + " element ids for " + std::to_string(mesh.triangles.size()) +
           " faces");
    }
    for (size_t f = 0; f < mesh.elements.size(); ++f) {
      if (mesh.elements[f] < 0) fail("face " + std::to_string(f) + " has negative element id");
    }
  }
}

}  // namespace meshquilt
