#include "mesh/measures.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace meshquilt {

Box3 bounding_box(const std::vector<Vec3>& points) {
  Box3 box;
  for (const Vec3& p : points) {
    box.lo = glm::min(box.lo, p);
    box.hi = glm::max(box.hi, p);
  }
  return box;
}

std::vector<FaceSphere> face_spheres(const TriMesh& mesh) {
  std::vector<FaceSphere> spheres;
  spheres.reserve(mesh.num_faces());
  for (const Tri& t : mesh.triangles) {
    const Vec3 centre = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
    double radius = 0.0;
    for (int32_t v : t) radius = std::max(radius, glm::length(mesh.positions[v] - centre));
    spheres.push_back({centre, radius * (1.0 + 1e-12)});
  }
  return spheres;
}

std::vector<FacePlane> face_planes(const TriMesh& mesh) {
  std::vector<FacePlane> planes(mesh.num_faces());
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Vec3 cross = glm::cross(b - a, c - a);
    const double length = glm::length(cross);
    const double longest2 = std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
    if (length > 0.0) planes[f].normal = cross / length;
    planes[f].planar = length > 1e-6 * longest2;
  }
  return planes;
}

double half_cotangent(const TriMesh& mesh, const Tri& t, int k) {
  const Vec3 a = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
  const Vec3 b = mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[k]];
  const double sine = glm::length(glm::cross(a, b));
  return sine > 0.0 ? 0.5 * std::clamp(glm::dot(a, b) / sine, -1e3, 1e3) : 0.0;
}

double mean_edge_length(const TriMesh& mesh) {
  if (mesh.num_faces() == 0) return 0.0;
  double sum = 0.0;
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) sum += glm::length(mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]);
  return sum / (3.0 * static_cast<double>(mesh.num_faces()));
}

std::vector<Vec3> vertex_normals(const TriMesh& mesh, const Vec3& without_area) {
  std::vector<Vec3> normals(mesh.num_vertices(), Vec3(0.0));
  for (const Tri& t : mesh.triangles) {
    // |cross| is twice the area, so summing cross products weights by area.
    const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  for (Vec3& n : normals) {
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : without_area;
  }
  return normals;
}

std::vector<Vec3> vertex_normals(const TriMesh& mesh) { return vertex_normals(mesh, Vec3(0.0, 0.0, 1.0)); }

}  // namespace meshquilt
