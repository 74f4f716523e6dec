//! Reading OFF (incl. [ST][C][N]OFF headers, `#` comments).

#include "mesh/io/formats.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {

TriMesh read_off(std::string_view text, const std::string& name) {
  TextCursor cursor{text.data(), text.data() + text.size()};
  auto fail = [&](const std::string& problem) {
    parse_fail(name, "line " + std::to_string(line_of(text, cursor.p)) + ": " + problem);
  };
  auto read_count = [&](const char* what) {
    int64_t value = 0;
    const std::string_view token = cursor.token(true);
    if (token.empty()) fail(std::string("missing ") + what);
    if (!parse_int(token, value) || value < 0 || value > std::numeric_limits<int32_t>::max()) {
      fail(std::string("bad ") + what + " '" + std::string(token) + "'");
    }
    return value;
  };

  // Header keyword: [ST][C][N][4][n]OFF; it is optional in the format, so a number may come first.
  cursor.skip_space(true);
  const char* keyword_start = cursor.p;
  std::string_view keyword = cursor.token(true);
  if (keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF") {
    const std::string_view prefix = keyword.substr(0, keyword.size() - 3);
    if (prefix.find('4') != std::string_view::npos || prefix.find('n') != std::string_view::npos) {
      fail("4D and nD OFF are not supported");
    }
    const char* after = cursor.p;
    cursor.skip_blanks();
    const std::string_view next = cursor.line_token();
    if (next == "BINARY") fail("binary OFF is not supported");
    cursor.p = after;
  } else {
    cursor.p = keyword_start;
  }
  const int64_t num_vertices = read_count("vertex count");
  const int64_t num_faces = read_count("face count");
  // The edge count is optional in practice; it may only sit on the counts' line.
  cursor.line_token();
  cursor.skip_line();

  // Each vertex takes at least "0 0 0\n" and each face "3 0 1 2\n": counts the rest of the file
  // cannot hold are refused before anything is allocated.
  const auto left = static_cast<int64_t>(text.size() - static_cast<size_t>(cursor.p - text.data()));
  if (num_vertices > left / 6 || num_faces > (left - 6 * num_vertices) / 8) {
    parse_fail(name, "OFF header declares " + std::to_string(num_vertices) + " vertices and " +
                         std::to_string(num_faces) + " faces, more than the " + std::to_string(left) +
                         " bytes after it can hold");
  }
  TriMesh mesh;
  // Reserve no more than the file can hold ("0 0 0\n", "3 0 1 2\n"): the counts may be hostile.
  const auto size = static_cast<int64_t>(text.size());
  mesh.positions.reserve(static_cast<size_t>(std::min(num_vertices, size / 6)));
  mesh.triangles.reserve(static_cast<size_t>(std::min(num_faces, size / 8)));
  for (int64_t v = 0; v < num_vertices; ++v) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = cursor.token(true);
      if (token.empty()) fail("file ends after " + std::to_string(v) + " of " + std::to_string(num_vertices) + " vertices");
      if (!parse_double(token, p[k])) fail("bad vertex coordinate '" + std::string(token) + "'");
    }
    mesh.positions.push_back(p);
    cursor.skip_line();  // colours, normals, texture coordinates
  }
  std::vector<int32_t> polygon;
  for (int64_t f = 0; f < num_faces; ++f) {
    const std::string_view token = cursor.token(true);
    if (token.empty()) fail("file ends after " + std::to_string(f) + " of " + std::to_string(num_faces) + " faces");
    int64_t size = 0;
    if (!parse_int(token, size)) fail("bad face size '" + std::string(token) + "'");
    if (size < 3) fail("face with fewer than 3 vertices");
    if (size > num_vertices) fail("face with more vertices than the mesh");
    polygon.clear();
    for (int64_t i = 0; i < size; ++i) {
      const std::string_view index_token = cursor.token(true);
      int64_t index = 0;
      if (index_token.empty()) fail("file ends inside face " + std::to_string(f));
      if (!parse_int(index_token, index)) fail("bad face index '" + std::string(index_token) + "'");
      polygon.push_back(checked_index(index, mesh.positions.size(),
                                    [&] { return name + ": face " + std::to_string(f) + ": "; }));
    }
    push_fan(mesh.triangles, polygon);
    cursor.skip_line();  // face colours
  }
  return mesh;
}

}  // namespace meshquilt::io
