#include "mesh/mesh_io.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "error.h"
#include "mesh/atomic_write.h"
#include "mesh/memory_budget.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

// ---------------------------------------------------------------------------------------------
// Shared helpers

[[noreturn]] void parse_fail(const std::string& name, const std::string& problem) {
  throw InputError(name + ": " + problem, ExitCode::invalid_mesh);
}

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string read_whole_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw IoError(ExitCode::file_unreadable, name + ": cannot open: is a directory");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ExitCode::file_unreadable, name + ": cannot open: " + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw IoError(ExitCode::file_unreadable, name + ": cannot open: cannot determine its size");
  in.seekg(0, std::ios::beg);
  // The text and the mesh parsed from it live together for a moment; a mesh takes at most about
  // as many bytes as its binary file and far fewer than its text.
  check_memory_budget(2.0 * static_cast<double>(size), name + ": reading this " + format_bytes(static_cast<double>(size)) + " file");
  std::string data(static_cast<size_t>(size), '\0');
  if (size > 0 && !in.read(data.data(), size)) {
    throw IoError(ExitCode::file_unreadable, name + ": cannot open: read failed: " + std::strerror(errno));
  }
  return data;
}

// 1-based line number of `at` inside `text`; only computed on the error path.
size_t line_of(std::string_view text, const char* at) {
  const size_t offset = static_cast<size_t>(std::max<std::ptrdiff_t>(0, at - text.data()));
  return 1 + static_cast<size_t>(std::count(text.data(), text.data() + std::min(offset, text.size()), '\n'));
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool is_space(char c) { return is_blank(c) || c == '\n'; }

// std::from_chars rejects a leading '+', which some writers emit.
bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

bool parse_int(std::string_view token, int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

// A forward cursor over text; tokens are runs of non-space characters.
struct TextCursor {
  const char* p;
  const char* end;

  bool at_end() const { return p >= end; }
  void skip_blanks() {
    while (p < end && is_blank(*p)) ++p;
  }
  // Skips spaces and newlines, and `#` comments to the end of their line when `comments` is set.
  void skip_space(bool comments) {
    while (p < end) {
      if (is_space(*p)) {
        ++p;
      } else if (comments && *p == '#') {
        skip_line();
      } else {
        break;
      }
    }
  }
  void skip_line() {
    const void* nl = std::memchr(p, '\n', static_cast<size_t>(end - p));
    p = nl ? static_cast<const char*>(nl) + 1 : end;
  }
  // The next token on the current line (empty at end of line or of text).
  std::string_view line_token() {
    skip_blanks();
    const char* start = p;
    while (p < end && !is_space(*p)) ++p;
    return {start, static_cast<size_t>(p - start)};
  }
  // The next token, crossing lines (and comments when `comments` is set).
  std::string_view token(bool comments) {
    skip_space(comments);
    const char* start = p;
    while (p < end && !is_space(*p) && !(comments && *p == '#')) ++p;
    return {start, static_cast<size_t>(p - start)};
  }
};

void push_fan(std::vector<Tri>& triangles, const std::vector<int32_t>& polygon) {
  for (size_t i = 1; i + 1 < polygon.size(); ++i) triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
}

// `where` builds the message prefix only on failure: this runs once per face corner.
template <typename Where>
int32_t checked_index(int64_t value, size_t num_vertices, Where&& where) {
  if (value < 0 || static_cast<uint64_t>(value) >= num_vertices) {
    throw InputError(where() + "vertex index " + std::to_string(value) + " outside [0, " +
                     std::to_string(num_vertices) + ")");
  }
  return static_cast<int32_t>(value);
}

// ---------------------------------------------------------------------------------------------
// OBJ

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

// ---------------------------------------------------------------------------------------------
// OFF

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

// ---------------------------------------------------------------------------------------------
// PLY

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

bool ply_type(std::string_view word, PlyType& type) {
  static const std::pair<std::string_view, PlyType> table[] = {
      {"char", PlyType::int8},     {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
      {"uint8", PlyType::uint8},   {"short", PlyType::int16},     {"int16", PlyType::int16},
      {"ushort", PlyType::uint16}, {"uint16", PlyType::uint16},   {"int", PlyType::int32},
      {"int32", PlyType::int32},   {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
      {"float", PlyType::float32}, {"float32", PlyType::float32}, {"double", PlyType::float64},
      {"float64", PlyType::float64}};
  for (const auto& [key, value] : table) {
    if (key == word) {
      type = value;
      return true;
    }
  }
  return false;
}

bool ply_is_float(PlyType type) { return type == PlyType::float32 || type == PlyType::float64; }

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::float32;  // value type (list items for a list)
  bool is_list = false;
  PlyType count_type = PlyType::uint8;
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { ascii, binary_little, binary_big };

// Reads binary PLY values with bounds checks, swapping bytes when the file's order differs.
class BinaryReader {
 public:
  BinaryReader(const char* begin, const char* end, bool swap) : p_(begin), end_(end), swap_(swap) {}

  bool read(PlyType type, double& value) {
    switch (type) {
      case PlyType::int8: return read_as<int8_t>(value);
      case PlyType::uint8: return read_as<uint8_t>(value);
      case PlyType::int16: return read_as<int16_t>(value);
      case PlyType::uint16: return read_as<uint16_t>(value);
      case PlyType::int32: return read_as<int32_t>(value);
      case PlyType::uint32: return read_as<uint32_t>(value);
      case PlyType::float32: return read_as<float>(value);
      case PlyType::float64: return read_as<double>(value);
    }
    return false;
  }
  bool skip(size_t bytes) {
    if (static_cast<size_t>(end_ - p_) < bytes) return false;
    p_ += bytes;
    return true;
  }
  size_t remaining() const { return static_cast<size_t>(end_ - p_); }
  static size_t min_row_bytes(const PlyElement& element) {
    size_t bytes = 0;
    for (const PlyProperty& property : element.properties) bytes += size_of(property.is_list ? property.count_type : property.type);
    return std::max<size_t>(bytes, 1);
  }

 private:
  static size_t size_of(PlyType type) {
    switch (type) {
      case PlyType::int8:
      case PlyType::uint8: return 1;
      case PlyType::int16:
      case PlyType::uint16: return 2;
      case PlyType::int32:
      case PlyType::uint32:
      case PlyType::float32: return 4;
      case PlyType::float64: return 8;
    }
    return 1;
  }

  template <typename T>
  bool read_as(double& value) {
    if (static_cast<size_t>(end_ - p_) < sizeof(T)) return false;
    char bytes[sizeof(T)];
    std::memcpy(bytes, p_, sizeof(T));
    if (swap_) std::reverse(bytes, bytes + sizeof(T));
    T raw;
    std::memcpy(&raw, bytes, sizeof(T));
    value = static_cast<double>(raw);
    p_ += sizeof(T);
    return true;
  }

  const char* p_;
  const char* end_;
  bool swap_;
};

// Reads ASCII PLY values token by token; an element need not sit on one line.
class AsciiReader {
 public:
  AsciiReader(const char* begin, const char* end) : cursor_{begin, end} {}

  bool read(PlyType type, double& value) {
    const std::string_view token = cursor_.token(false);
    if (ply_is_float(type)) return parse_double(token, value);
    int64_t integer = 0;
    if (!parse_int(token, integer)) return false;
    value = static_cast<double>(integer);
    return true;
  }
  size_t remaining() const { return static_cast<size_t>(cursor_.end - cursor_.p); }
  // Each value takes at least one character and one separator.
  static size_t min_row_bytes(const PlyElement& element) { return std::max<size_t>(2 * element.properties.size(), 1); }

 private:
  TextCursor cursor_;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;
};

PlyHeader read_ply_header(std::string_view data, const std::string& name) {
  PlyHeader header;
  auto fail = [&](const std::string& problem) { parse_fail(name, "PLY header: " + problem); };
  size_t pos = 0;
  bool first = true;
  bool have_format = false;
  while (true) {
    if (pos >= data.size()) fail("no end_header line");
    size_t eol = data.find('\n', pos);
    if (eol == std::string_view::npos) fail("no end_header line");
    TextCursor line{data.data() + pos, data.data() + eol};
    pos = eol + 1;
    const std::string_view keyword = line.line_token();
    if (first) {
      if (keyword != "ply") fail("file does not start with 'ply'");
      first = false;
      continue;
    }
    if (keyword == "format") {
      const std::string_view format = line.line_token();
      if (format == "ascii") {
        header.format = PlyFormat::ascii;
      } else if (format == "binary_little_endian") {
        header.format = PlyFormat::binary_little;
      } else if (format == "binary_big_endian") {
        header.format = PlyFormat::binary_big;
      } else {
        fail("unknown format '" + std::string(format) + "'");
      }
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(line.line_token());
      if (!parse_int(line.line_token(), element.count) || element.count < 0) {
        fail("bad count for element '" + element.name + "'");
      }
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("property before any element");
      PlyProperty property;
      std::string_view word = line.line_token();
      if (word == "list") {
        property.is_list = true;
        if (!ply_type(line.line_token(), property.count_type) || ply_is_float(property.count_type)) {
          fail("bad list count type");
        }
        word = line.line_token();
      }
      if (!ply_type(word, property.type)) fail("unknown property type '" + std::string(word) + "'");
      property.name = std::string(line.line_token());
      if (property.name.empty()) fail("property without a name");
      header.elements.back().properties.push_back(std::move(property));
    } else if (keyword == "end_header") {
      break;
    } else if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) {
      continue;
    } else {
      fail("unknown header line '" + std::string(keyword) + "'");
    }
  }
  if (!have_format) fail("no format line");
  header.data_offset = pos;
  return header;
}

int find_property(const PlyElement& element, std::initializer_list<std::string_view> names) {
  for (size_t i = 0; i < element.properties.size(); ++i) {
    for (std::string_view n : names) {
      if (element.properties[i].name == n) return static_cast<int>(i);
    }
  }
  return -1;
}

template <typename Reader>
void read_ply_body(Reader& reader, const PlyHeader& header, TriMesh& mesh, bool& has_element_ids,
                   const std::string& name) {
  std::vector<int32_t> polygon;
  std::vector<int32_t> elements, sources;
  bool seen_vertices = false;
  bool has_sources = false;
  // Honest counts: every element's items need at least min_row_bytes each, so a header that
  // declares more than the data can hold (2^31 faces in a 1 KB file) is refused up front, and
  // so is a mesh the memory budget cannot take, before anything is allocated.
  {
    size_t left = reader.remaining();
    double mesh_bytes = 0.0;
    for (const PlyElement& element : header.elements) {
      const size_t row = reader.min_row_bytes(element);
      if (static_cast<uint64_t>(element.count) > left / row) {
        parse_fail(name, "PLY header declares " + std::to_string(element.count) + " '" + element.name +
                             "' items of at least " + std::to_string(row) + " bytes, more than the " +
                             std::to_string(reader.remaining()) + " bytes of data can hold");
      }
      left -= static_cast<size_t>(element.count) * row;
      if (element.name == "vertex") {
        if (element.count > std::numeric_limits<int32_t>::max()) {
          throw InputError(name + ": PLY header declares " + std::to_string(element.count) +
                               " vertices, more than 32-bit vertex indices can address",
                           ExitCode::too_large);
        }
        mesh_bytes += 24.0 * static_cast<double>(element.count);
      } else if (element.name == "face") {
        mesh_bytes += 16.0 * static_cast<double>(element.count);
      }
    }
    check_memory_budget(mesh_bytes, name + ": the mesh its PLY header declares");
  }
  for (const PlyElement& element : header.elements) {
    auto truncated = [&](int64_t item) {
      parse_fail(name, "PLY data ends or is malformed in element '" + element.name + "' item " + std::to_string(item) +
                           " of " + std::to_string(element.count));
    };
    // Reserve no more than the remaining bytes could hold (a hostile count must not exhaust memory).
    const auto bound = static_cast<int64_t>(reader.remaining() / reader.min_row_bytes(element));
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    int ix = -1, iy = -1, iz = -1, iindices = -1, ielement = -1, isource = -1;
    if (is_vertex) {
      ix = find_property(element, {"x"});
      iy = find_property(element, {"y"});
      iz = find_property(element, {"z"});
      if (ix < 0 || iy < 0 || iz < 0) parse_fail(name, "PLY vertex element lacks x, y or z");
      if (element.properties[ix].is_list || element.properties[iy].is_list || element.properties[iz].is_list) {
        parse_fail(name, "PLY vertex x, y, z must be scalars");
      }
      mesh.positions.reserve(static_cast<size_t>(std::min(element.count, bound)));
      seen_vertices = true;
    } else if (is_face) {
      iindices = find_property(element, {"vertex_indices", "vertex_index"});
      if (iindices < 0 || !element.properties[iindices].is_list) {
        parse_fail(name, "PLY face element lacks a vertex_indices list");
      }
      ielement = find_property(element, {"element"});
      if (ielement >= 0 && element.properties[ielement].is_list) ielement = -1;
      has_element_ids = ielement >= 0;
      isource = find_property(element, {"source"});
      if (isource >= 0 && element.properties[isource].is_list) isource = -1;
      has_sources = isource >= 0;
      mesh.triangles.reserve(static_cast<size_t>(std::min(element.count, bound)));
    }
    for (int64_t item = 0; item < element.count; ++item) {
      Vec3 p(0.0);
      int32_t element_id = 0, source_id = 0;
      for (size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        const int index = static_cast<int>(k);
        double value = 0.0;
        if (!property.is_list) {
          if (!reader.read(property.type, value)) truncated(item);
          if (index == ix) p.x = value;
          if (index == iy) p.y = value;
          if (index == iz) p.z = value;
          if (index == ielement) {
            if (!(value >= 0.0 && value <= std::numeric_limits<int32_t>::max())) {
              parse_fail(name, "PLY face " + std::to_string(item) + " has a bad element id");
            }
            element_id = static_cast<int32_t>(value);
          }
          if (index == isource) {
            if (!(value >= 0.0 && value <= std::numeric_limits<int32_t>::max())) {
              parse_fail(name, "PLY face " + std::to_string(item) + " has a bad source id");
            }
            source_id = static_cast<int32_t>(value);
          }
          continue;
        }
        double count_value = 0.0;
        if (!reader.read(property.count_type, count_value)) truncated(item);
        if (count_value < 0) truncated(item);
        const auto count = static_cast<int64_t>(count_value);
        if (index != iindices) {
          for (int64_t i = 0; i < count; ++i) {
            if (!reader.read(property.type, value)) truncated(item);
          }
          continue;
        }
        if (!seen_vertices) parse_fail(name, "PLY face element comes before the vertex element");
        if (count < 3) parse_fail(name, "PLY face " + std::to_string(item) + " has fewer than 3 vertices");
        polygon.clear();
        for (int64_t i = 0; i < count; ++i) {
          if (!reader.read(property.type, value)) truncated(item);
          if (value != std::floor(value)) parse_fail(name, "PLY face " + std::to_string(item) + " has a non-integer index");
          polygon.push_back(checked_index(static_cast<int64_t>(value), mesh.positions.size(),
                                          [&] { return name + ": PLY face " + std::to_string(item) + ": "; }));
        }
      }
      if (is_vertex) {
        mesh.positions.push_back(p);
      } else if (is_face) {
        const size_t before = mesh.triangles.size();
        push_fan(mesh.triangles, polygon);
        if (has_element_ids) elements.insert(elements.end(), mesh.triangles.size() - before, element_id);
        if (has_sources) sources.insert(sources.end(), mesh.triangles.size() - before, source_id);
      }
    }
  }
  if (has_element_ids) mesh.elements = std::move(elements);
  if (has_sources) mesh.sources = std::move(sources);
}

TriMesh read_ply(std::string_view data, const std::string& name) {
  const PlyHeader header = read_ply_header(data, name);
  TriMesh mesh;
  bool has_element_ids = false;
  const char* begin = data.data() + header.data_offset;
  const char* end = data.data() + data.size();
  if (header.format == PlyFormat::ascii) {
    AsciiReader reader(begin, end);
    read_ply_body(reader, header, mesh, has_element_ids, name);
  } else {
    const bool file_little = header.format == PlyFormat::binary_little;
    const bool host_little = std::endian::native == std::endian::little;
    BinaryReader reader(begin, end, file_little != host_little);
    read_ply_body(reader, header, mesh, has_element_ids, name);
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// STL

struct VertexKey {
  double x, y, z;
  bool operator==(const VertexKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct VertexKeyHash {
  size_t operator()(const VertexKey& k) const {
    auto bits = [](double d) { return std::bit_cast<uint64_t>(d + 0.0); };  // +0.0 folds -0 into 0
    uint64_t h = bits(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(k.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= bits(k.z) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h ^ (h >> 31));
  }
};

// STL stores a triangle soup; vertices with identical coordinates are shared so the result is an
// indexed mesh (as other STL readers do). Near-coincident vertices are left to weld_vertices.
class SoupIndexer {
 public:
  explicit SoupIndexer(TriMesh& mesh) : mesh_(mesh) {}
  int32_t index(const Vec3& p) {
    const auto [it, inserted] = map_.try_emplace(VertexKey{p.x, p.y, p.z}, static_cast<int32_t>(mesh_.positions.size()));
    if (inserted) mesh_.positions.push_back(p);
    return it->second;
  }
  void reserve(size_t n) { map_.reserve(n); }

 private:
  TriMesh& mesh_;
  std::unordered_map<VertexKey, int32_t, VertexKeyHash> map_;
};

TriMesh read_stl(std::string_view data, const std::string& name) {
  TriMesh mesh;
  SoupIndexer indexer(mesh);
  if (data.size() >= 84) {
    uint32_t count = 0;
    std::memcpy(&count, data.data() + 80, 4);
    if (std::endian::native == std::endian::big) {
      count = (count >> 24) | ((count >> 8) & 0xFF00u) | ((count << 8) & 0xFF0000u) | (count << 24);
    }
    // The size decides, not the header (binary headers may start with "solid" too); trailing
    // bytes after the triangles are tolerated when the file cannot be ASCII.
    const uint64_t expected = 84 + 50 * static_cast<uint64_t>(count);
    const bool looks_ascii = data.substr(0, 5) == "solid";
    if (expected == data.size() || (expected < data.size() && !looks_ascii)) {
      mesh.triangles.reserve(count);
      indexer.reserve(count);
      for (uint32_t f = 0; f < count; ++f) {
        const char* record = data.data() + 84 + 50 * static_cast<size_t>(f);
        Tri tri;
        for (int c = 0; c < 3; ++c) {
          float xyz[3];
          std::memcpy(xyz, record + 12 + 12 * c, 12);
          tri[c] = indexer.index(Vec3(xyz[0], xyz[1], xyz[2]));
        }
        mesh.triangles.push_back(tri);
      }
      return mesh;
    }
  }
  TextCursor cursor{data.data(), data.data() + data.size()};
  if (cursor.token(false) != "solid") {
    if (data.size() >= 84) parse_fail(name, "binary STL size does not match its triangle count (truncated?)");
    parse_fail(name, "not an STL file");
  }
  std::vector<int32_t> polygon;
  bool in_loop = false;
  for (std::string_view token = cursor.token(false); !token.empty(); token = cursor.token(false)) {
    if (token == "vertex") {
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        const std::string_view number = cursor.token(false);
        if (!parse_double(number, p[k])) {
          parse_fail(name, "line " + std::to_string(line_of(data, cursor.p)) + ": bad vertex coordinate");
        }
      }
      polygon.push_back(indexer.index(p));
      in_loop = true;
    } else if (token == "endloop" || token == "endfacet") {
      if (!in_loop) continue;
      if (polygon.size() < 3) {
        parse_fail(name, "line " + std::to_string(line_of(data, cursor.p)) + ": facet with fewer than 3 vertices");
      }
      push_fan(mesh.triangles, polygon);
      polygon.clear();
      in_loop = false;
    }
  }
  if (in_loop) parse_fail(name, "file ends inside a facet");
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Writing

void append_double(std::string& out, double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);  // shortest round-trip form
  out.append(buffer, end);
}

void append_int(std::string& out, int64_t value) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, end);
}

template <typename T>
void append_binary(std::string& out, T value, bool little) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (little != (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

void append_vec(std::string& out, const Vec3& p) {
  append_double(out, p.x);
  out += ' ';
  append_double(out, p.y);
  out += ' ';
  append_double(out, p.z);
}

std::string format_ply(const TriMesh& mesh, bool binary) {
  const bool with_elements = !mesh.elements.empty();
  std::string out;
  out.reserve(256 + (binary ? 24 * mesh.positions.size() + 17 * mesh.triangles.size()
                            : 60 * mesh.positions.size() + 30 * mesh.triangles.size()));
  out += "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by meshquilt\nelement vertex ";
  append_int(out, static_cast<int64_t>(mesh.positions.size()));
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  append_int(out, static_cast<int64_t>(mesh.triangles.size()));
  out += "\nproperty list uchar int vertex_indices\n";
  if (with_elements) out += "property int element\n";
  const bool with_sources = mesh.sources.size() == mesh.triangles.size() && !mesh.sources.empty();
  if (with_sources) out += "property int source\n";
  out += "end_header\n";
  for (const Vec3& p : mesh.positions) {
    if (binary) {
      append_binary(out, p.x, true);
      append_binary(out, p.y, true);
      append_binary(out, p.z, true);
    } else {
      append_vec(out, p);
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

Vec3 face_normal(const TriMesh& mesh, const Tri& t) {
  const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : Vec3(0.0);
}

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

}  // namespace

// Our own parsers rather than OpenMesh's: see mesh_io.h (element ids, non-manifold faces, speed).
// OpenMesh stays the independent reference in the tests.
TriMesh read_mesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string ext = lower_extension(file);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    throw IoError(ExitCode::unknown_format, name + ": unknown mesh format '" + ext + "' (expected .obj .ply .off .stl)");
  }
  const std::string data = read_whole_file(file);
  return parse_mesh(data, ext, name);
}

TriMesh parse_mesh(std::string_view data, const std::string& extension, const std::string& name) {
  std::string ext = extension;
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    throw IoError(ExitCode::unknown_format, name + ": unknown mesh format '" + ext + "' (expected .obj .ply .off .stl)");
  }
  TriMesh mesh;
  if (ext == ".obj") {
    mesh = read_obj(data, name);
  } else if (ext == ".ply") {
    mesh = read_ply(data, name);
  } else if (ext == ".off") {
    mesh = read_off(data, name);
  } else {
    mesh = read_stl(data, name);
  }
  validate_mesh(mesh, name);
  return mesh;
}

void write_mesh(const TriMesh& mesh, const std::filesystem::path& file, const WriteOptions& options) {
  const std::string name = file.string();
  const std::string ext = lower_extension(file);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    throw IoError(ExitCode::unknown_format, name + ": unknown mesh format '" + ext + "' (expected .obj .ply .off .stl)");
  }
  if (!mesh.elements.empty() && mesh.elements.size() != mesh.triangles.size()) {
    throw IoError(ExitCode::write_failed, name + ": " + std::to_string(mesh.elements.size()) + " element ids for " +
                                              std::to_string(mesh.triangles.size()) + " faces");
  }
  const auto num_vertices = static_cast<uint64_t>(mesh.positions.size());
  for (const Tri& t : mesh.triangles) {
    for (int32_t i : t) {
      if (i < 0 || static_cast<uint64_t>(i) >= num_vertices) {
        throw IoError(ExitCode::write_failed, name + ": face vertex index " + std::to_string(i) + " out of range");
      }
    }
  }

  std::string content;
  if (ext == ".ply") {
    content = format_ply(mesh, options.binary);
  } else if (ext == ".obj") {
    content = format_obj(mesh);
  } else if (ext == ".off") {
    content = format_off(mesh);
  } else {
    content = format_stl(mesh, options.binary);
  }

  write_file_atomic(file, content, options.cancel);
}

}  // namespace meshquilt
