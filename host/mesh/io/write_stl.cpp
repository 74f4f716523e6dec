//! Writing STL, binary or ASCII, with per-face normals.

#include "mesh/io/formats.h"

#include <cstdint>
#include <string>

#include <glm/geometric.hpp>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {
namespace {

Vec3 face_normal(const TriMesh& mesh, const Tri& t) {
  const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : Vec3(0.0);
}

}  // namespace

std::string format_stl(const TriMesh& mesh, bool binary) {
  std::string out;
  if (binary) {
    out.reserve(84 + 50 * mesh.triangles.size());
    // The header must not start with "solid", or readers take the file for ASCII.
    std::string header = "binary STL written by meshquilt";
    header.resize(80, ' ');
    out += header;
    append_binary(out, static_cast<uint32_t>(mesh.triangles.size()), true);
    for (const Tri& t : mesh.triangles) {
      const Vec3 n = face_normal(mesh, t);
      for (int k = 0; k < 3; ++k) append_binary(out, static_cast<float>(n[k]), true);
      for (int32_t i : t) {
        for (int k = 0; k < 3; ++k) append_binary(out, static_cast<float>(mesh.positions[i][k]), true);
      }
      append_binary(out, uint16_t{0}, true);
    }
    return out;
  }
  out.reserve(64 + 200 * mesh.triangles.size());
  out += "solid meshquilt\n";
  for (const Tri& t : mesh.triangles) {
    out += "facet normal ";
    append_vec(out, face_normal(mesh, t));
    out += "\n outer loop\n";
    for (int32_t i : t) {
      out += "  vertex ";
      append_vec(out, mesh.positions[i]);
      out += '\n';
    }
    out += " endloop\nendfacet\n";
  }
  out += "endsolid meshquilt\n";
  return out;
}

}  // namespace meshquilt::io
