//! Writing PLY, binary little endian or ASCII, with face properties `element` and `source` and,
//! when the mesh has them, vertex colours `red green blue` (uchar) and swatch vertices `origin`.

#include "mesh/io/formats.h"

#include <cstdint>
#include <string>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {

std::string format_ply(const TriMesh& mesh, bool binary) {
  const bool with_elements = !mesh.elements.empty();
  const bool with_colors = !mesh.colors.empty() && mesh.colors.size() == mesh.positions.size();
  const bool with_origins = !mesh.origins.empty() && mesh.origins.size() == mesh.positions.size();
  const bool with_sources = mesh.sources.size() == mesh.triangles.size() && !mesh.sources.empty();
  // A binary file's size is known to the byte: one allocation, never a copy of a grown buffer.
  const size_t vertex_bytes = 24 + (with_colors ? 3 : 0) + (with_origins ? 4 : 0);
  const size_t face_bytes = 13 + (with_elements ? 4 : 0) + (with_sources ? 4 : 0);
  std::string out;
  out.reserve(512 + (binary ? vertex_bytes * mesh.positions.size() + face_bytes * mesh.triangles.size()
                            : 60 * mesh.positions.size() + 30 * mesh.triangles.size()));
  out += "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by meshquilt\nelement vertex ";
  append_int(out, static_cast<int64_t>(mesh.positions.size()));
  out += "\nproperty double x\nproperty double y\nproperty double z\n";
  if (with_colors) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (with_origins) out += "property int origin\n";
  out += "element face ";
  append_int(out, static_cast<int64_t>(mesh.triangles.size()));
  out += "\nproperty list uchar int vertex_indices\n";
  if (with_elements) out += "property int element\n";
  if (with_sources) out += "property int source\n";
  out += "end_header\n";
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    if (binary) {
      append_binary(out, p.x, true);
      append_binary(out, p.y, true);
      append_binary(out, p.z, true);
      if (with_colors)
        for (uint8_t c : mesh.colors[v]) out += static_cast<char>(c);
      if (with_origins) append_binary(out, mesh.origins[v], true);
    } else {
      append_vec(out, p);
      if (with_colors)
        for (uint8_t c : mesh.colors[v]) {
          out += ' ';
          append_int(out, c);
        }
      if (with_origins) {
        out += ' ';
        append_int(out, mesh.origins[v]);
      }
      out += '\n';
    }
  }
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Tri& t = mesh.triangles[f];
    if (binary) {
      out += static_cast<char>(3);
      for (int32_t i : t) append_binary(out, i, true);
      if (with_elements) append_binary(out, mesh.elements[f], true);
      if (with_sources) append_binary(out, mesh.sources[f], true);
    } else {
      out += '3';
      for (int32_t i : t) {
        out += ' ';
        append_int(out, i);
      }
      if (with_elements) {
        out += ' ';
        append_int(out, mesh.elements[f]);
      }
      if (with_sources) {
        out += ' ';
        append_int(out, mesh.sources[f]);
      }
      out += '\n';
    }
  }
  return out;
}

}  // namespace meshquilt::io
