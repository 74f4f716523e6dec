#include "mesh/base_mesh.h"

#include <algorithm>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

// Faces sharing an undirected edge: pairs (face, local edge index); refuses three or more.
std::unordered_map<uint64_t, std::vector<std::pair<int32_t, int>>> edge_faces(const TriMesh& mesh,
                                                                             const std::string& source) {
  std::unordered_map<uint64_t, std::vector<std::pair<int32_t, int>>> faces;
  faces.reserve(mesh.num_faces() * 2);
  for (size_t f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      auto& list = faces[undirected_edge_key(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3])];
      list.emplace_back(static_cast<int32_t>(f), k);
      if (list.size() > 2)
        throw InputError(source + ": non-manifold base: an edge is shared by " + std::to_string(list.size()) +
                         " faces (vertices " + std::to_string(mesh.triangles[f][k]) + " and " +
                         std::to_string(mesh.triangles[f][(k + 1) % 3]) + ")");
    }
  return faces;
}

}  // namespace

TriMesh prepare_base(const TriMesh& input, const std::string& source) {
  validate_mesh(input, source);
  TriMesh mesh = weld_vertices(input);
  mesh.elements.clear();
  if (mesh.num_faces() == 0) throw InputError(source + ": no faces left after welding coincident vertices");
  double total_area = 0.0;
  for (const Tri& t : mesh.triangles)
    total_area += glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                         mesh.positions[t[2]] - mesh.positions[t[0]]));
  const double diagonal = glm::length(bounding_box(mesh.positions).extent());
  if (!(total_area > 1e-12 * diagonal * diagonal))
    throw InputError(source + ": no face has area (each has its corners on a line)");
  const auto faces_of_edge = edge_faces(mesh, source);

  // Breadth-first over faces: a neighbour that runs the shared edge the same way is flipped.
  const size_t face_count = mesh.num_faces();
  std::vector<int8_t> flip(face_count, -1);
  std::vector<int32_t> queue;
  for (size_t start = 0; start < face_count; ++start) {
    if (flip[start] >= 0) continue;
    flip[start] = 0;
    queue.assign(1, static_cast<int32_t>(start));
    std::vector<int32_t> component;
    bool closed = true;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int32_t f = queue[head];
      component.push_back(f);
      const Tri& t = mesh.triangles[f];
      for (int k = 0; k < 3; ++k) {
        // Direction of the edge as f will finally run it.
        int32_t a = t[k], b = t[(k + 1) % 3];
        if (flip[f]) std::swap(a, b);
        const auto& sharing = faces_of_edge.at(undirected_edge_key(a, b));
        if (sharing.size() < 2) closed = false;
        for (const auto& [g, local] : sharing) {
          if (g == f) continue;
          const bool same_way = mesh.triangles[g][local] == a;  // g runs a -> b too
          const int8_t wanted = same_way ? 1 : 0;
          if (flip[g] < 0) {
            flip[g] = wanted;
            queue.push_back(g);
          } else if (flip[g] != wanted) {
            throw InputError(source + ": non-orientable base (a Moebius-like component around face " +
                             std::to_string(g) + ")");
          }
        }
      }
    }
    // Outward: closed, a positive signed volume; open (a scan with a hole at the neck), a positive
    // volume of the cone from the component's centroid, i.e. the faces mostly look away from it.
    // A flat or nearly flat open sheet has no outside: it keeps the file's own orientation.
    Vec3 centre(0.0);
    double area = 0.0;
    for (int32_t f : component) {
      const Tri& t = mesh.triangles[f];
      const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
      const double w = 0.5 * glm::length(glm::cross(b - a, c - a));
      centre += w * (a + b + c) / 3.0;
      area += w;
    }
    if (area > 0.0) centre /= area;
    double volume = 0.0, extent = 0.0;
    for (int32_t f : component) {
      Tri t = mesh.triangles[f];
      if (flip[f]) std::swap(t[1], t[2]);
      const Vec3 a = mesh.positions[t[0]] - centre, b = mesh.positions[t[1]] - centre, c = mesh.positions[t[2]] - centre;
      volume += glm::dot(a, glm::cross(b, c)) / 6.0;
      extent = std::max({extent, glm::length(a), glm::length(b), glm::length(c)});
    }
    if (!closed && std::abs(volume) <= 1e-3 * area * extent) continue;
    if (volume < 0.0)
      for (int32_t f : component) flip[f] = static_cast<int8_t>(1 - flip[f]);
  }
  for (size_t f = 0; f < face_count; ++f)
    if (flip[f]) std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
  return mesh;
}

std::vector<int32_t> prepared_vertex_sources(const TriMesh& mesh) {
  // weld_vertices keeps, in index order, the representatives used by a face that does not collapse.
  const std::vector<int32_t> representative = weld_representatives(mesh.positions, kWeldTolerance);
  std::vector<char> used(mesh.positions.size(), 0);
  for (const Tri& t : mesh.triangles) {
    const Tri w = {representative[t[0]], representative[t[1]], representative[t[2]]};
    if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2])
      for (int32_t v : w) used[v] = 1;
  }
  std::vector<int32_t> sources;
  for (size_t v = 0; v < used.size(); ++v)
    if (used[v]) sources.push_back(static_cast<int32_t>(v));
  return sources;
}

TriMesh posed_base(const TriMesh& prepared, const std::vector<int32_t>& sources, const TriMesh& frame) {
  TriMesh posed = prepared;
  for (size_t v = 0; v < sources.size(); ++v) posed.positions[v] = frame.positions[sources[v]];
  return posed;
}

}  // namespace meshquilt
