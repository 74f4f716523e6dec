//! Writing OFF.

#include "mesh/io/formats.h"

#include <cstdint>
#include <string>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {

std::string format_off(const TriMesh& mesh) {
  std::string out;
  out.reserve(64 + 60 * mesh.positions.size() + 30 * mesh.triangles.size());
  out += "OFF\n";
  append_int(out, static_cast<int64_t>(mesh.positions.size()));
  out += ' ';
  append_int(out, static_cast<int64_t>(mesh.triangles.size()));
  out += " 0\n";
  for (const Vec3& p : mesh.positions) {
    append_vec(out, p);
    out += '\n';
  }
  for (const Tri& t : mesh.triangles) {
    out += '3';
    for (int32_t i : t) {
      out += ' ';
      append_int(out, i);
    }
    out += '\n';
  }
  return out;
}

}  // namespace meshquilt::io
