//! Reading OBJ: `v` and `f` lines, element ids from `element_N` groups.

#include "mesh/io/formats.h"

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {
namespace {

// Element ids come back only from files that name every face's group `element_N`, as
// write_mesh does; other groups (materials, parts) carry no element meaning.
bool element_group_id(std::string_view name, int32_t& id) {
  constexpr std::string_view prefix = "element_";
  if (name.substr(0, prefix.size()) != prefix) return false;
  int64_t value = 0;
  if (!parse_int(name.substr(prefix.size()), value) || value < 0 || value > std::numeric_limits<int32_t>::max()) {
    return false;
  }
  id = static_cast<int32_t>(value);
  return true;
}

}  // namespace

TriMesh read_obj(std::string_view text, const std::string& name) {
  TriMesh mesh;
  mesh.positions.reserve(text.size() / 40);
  mesh.triangles.reserve(text.size() / 20);
  std::vector<int32_t> elements;
  bool all_faces_grouped = true;
  int32_t group = -1;
  std::vector<int32_t> polygon;
  TextCursor cursor{text.data(), text.data() + text.size()};
  while (!cursor.at_end()) {
    const char* line_start = cursor.p;
    auto fail = [&](const std::string& problem) {
      parse_fail(name, "line " + std::to_string(line_of(text, line_start)) + ": " + problem);
    };
    const std::string_view keyword = cursor.line_token();
    if (keyword == "v") {
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        if (!parse_double(cursor.line_token(), p[k])) fail("bad vertex coordinate");
      }
      mesh.positions.push_back(p);
    } else if (keyword == "f") {
      polygon.clear();
      for (std::string_view token = cursor.line_token(); !token.empty(); token = cursor.line_token()) {
        // Only the position index of v, v/vt, v//vn and v/vt/vn matters here.
        const std::string_view position = token.substr(0, token.find('/'));
        int64_t value = 0;
        if (!parse_int(position, value) || value == 0) fail("bad face index '" + std::string(token) + "'");
        // Negative indices count back from the last vertex read so far.
        const int64_t resolved = value > 0 ? value - 1 : static_cast<int64_t>(mesh.positions.size()) + value;
        if (resolved < 0 || resolved > std::numeric_limits<int32_t>::max()) {
          fail("face index " + std::to_string(value) + " out of range");
        }
        polygon.push_back(static_cast<int32_t>(resolved));
      }
      if (polygon.size() < 3) fail("face with fewer than 3 vertices");
      const size_t before = mesh.triangles.size();
      push_fan(mesh.triangles, polygon);
      if (group < 0) all_faces_grouped = false;
      elements.insert(elements.end(), mesh.triangles.size() - before, group);
    } else if (keyword == "g" || keyword == "o") {
      int32_t id = -1;
      group = element_group_id(cursor.line_token(), id) ? id : -1;
    }
    cursor.skip_line();
  }
  if (all_faces_grouped) mesh.elements = std::move(elements);
  return mesh;
}

}  // namespace meshquilt::io
