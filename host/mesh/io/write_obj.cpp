//! Writing OBJ, element ids as `g element_N` groups.

#include "mesh/io/formats.h"

#include <cstdint>
#include <string>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {

std::string format_obj(const TriMesh& mesh) {
  std::string out;
  out.reserve(64 + 60 * mesh.positions.size() + 30 * mesh.triangles.size());
  out += "# written by meshquilt\n";
  for (const Vec3& p : mesh.positions) {
    out += "v ";
    append_vec(out, p);
    out += '\n';
  }
  int64_t group = -1;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!mesh.elements.empty() && mesh.elements[f] != group) {
      group = mesh.elements[f];
      out += "g element_";
      append_int(out, group);
      out += '\n';
    }
    out += 'f';
    for (int32_t i : mesh.triangles[f]) {
      out += ' ';
      append_int(out, static_cast<int64_t>(i) + 1);
    }
    out += '\n';
  }
  return out;
}

}  // namespace meshquilt::io
