#include "surface/surface_types.h"

#include <glm/geometric.hpp>

#include "mesh/measures.h"
#include "mesh/topology.h"

namespace meshquilt {

BaseSurface::BaseSurface(const TriMesh& base) : mesh(base) {
  vertex_normals = meshquilt::vertex_normals(base);
  face_normals.resize(base.num_faces());
  face_areas.resize(base.num_faces());
  vertex_faces.resize(base.num_vertices());
  face_across = face_neighbors(base);
  edges.resize(base.num_vertices());
  diagonal = glm::length(bounding_box(base.positions).extent());
  for (size_t f = 0; f < base.num_faces(); ++f) {
    const Tri& t = base.triangles[f];
    const Vec3 n = glm::cross(base.positions[t[1]] - base.positions[t[0]], base.positions[t[2]] - base.positions[t[0]]);
    const double len = glm::length(n);
    face_areas[f] = 0.5 * len;
    face_normals[f] = len > 0.0 ? n / len : Vec3(0.0);
    area += face_areas[f];
    for (int k = 0; k < 3; ++k) {
      vertex_faces[t[k]].push_back(static_cast<int32_t>(f));
      const int32_t a = t[k], b = t[(k + 1) % 3];
      const double length = glm::distance(base.positions[a], base.positions[b]);
      // Each undirected edge once per side; duplicates from the second face are harmless.
      edges[a].emplace_back(b, length);
      edges[b].emplace_back(a, length);
    }
  }
}

Vec3 BaseSurface::position(const SurfacePoint& p) const {
  const Tri& t = mesh.triangles[p.face];
  return (1.0 - p.bary.x - p.bary.y) * mesh.positions[t[0]] + p.bary.x * mesh.positions[t[1]] +
         p.bary.y * mesh.positions[t[2]];
}

Vec3 BaseSurface::normal(const SurfacePoint& p) const {
  const Tri& t = mesh.triangles[p.face];
  const Vec3 n = (1.0 - p.bary.x - p.bary.y) * vertex_normals[t[0]] + p.bary.x * vertex_normals[t[1]] +
                 p.bary.y * vertex_normals[t[2]];
  const double len = glm::length(n);
  return len > 0.0 ? n / len : face_normals[p.face];
}

}  // namespace meshquilt
