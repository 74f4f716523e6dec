//! Reading PLY: ASCII and binary little/big endian, any scalar types.

#include "mesh/io/formats.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/memory_budget.h"

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {
namespace {

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

// Honest counts: every element's items need at least min_row_bytes each, so a header that
// declares more than the data can hold (2^31 faces in a 1 KB file) is refused up front, and
// so is a mesh the memory budget cannot take, before anything is allocated.
template <typename Reader>
void check_ply_counts(const Reader& reader, const PlyHeader& header, const std::string& name) {
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
                         ErrorKind::too_large);
      }
      mesh_bytes += 24.0 * static_cast<double>(element.count);
    } else if (element.name == "face") {
      mesh_bytes += 16.0 * static_cast<double>(element.count);
    }
  }
  check_memory_budget(mesh_bytes, name + ": the mesh its PLY header declares");
}

template <typename Reader>
void read_ply_body(Reader& reader, const PlyHeader& header, TriMesh& mesh, bool& has_element_ids,
                   const std::string& name) {
  std::vector<int32_t> polygon;
  std::vector<int32_t> elements, sources;
  bool seen_vertices = false;
  bool has_sources = false;
  check_ply_counts(reader, header, name);
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
    int icolor[3] = {-1, -1, -1};
    int iorigin = -1;
    bool has_colors = false;
    if (is_vertex) {
      ix = find_property(element, {"x"});
      iy = find_property(element, {"y"});
      iz = find_property(element, {"z"});
      if (ix < 0 || iy < 0 || iz < 0) parse_fail(name, "PLY vertex element lacks x, y or z");
      if (element.properties[ix].is_list || element.properties[iy].is_list || element.properties[iz].is_list) {
        parse_fail(name, "PLY vertex x, y, z must be scalars");
      }
      icolor[0] = find_property(element, {"red", "r"});
      icolor[1] = find_property(element, {"green", "g"});
      icolor[2] = find_property(element, {"blue", "b"});
      has_colors = icolor[0] >= 0 && icolor[1] >= 0 && icolor[2] >= 0 && !element.properties[icolor[0]].is_list &&
                   !element.properties[icolor[1]].is_list && !element.properties[icolor[2]].is_list;
      iorigin = find_property(element, {"origin"});
      if (iorigin >= 0 && element.properties[iorigin].is_list) iorigin = -1;
      mesh.positions.reserve(static_cast<size_t>(std::min(element.count, bound)));
      if (has_colors) mesh.colors.reserve(static_cast<size_t>(std::min(element.count, bound)));
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
      std::array<uint8_t, 3> color{0, 0, 0};
      int32_t origin = -1;
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
          if (index == iorigin && value >= -1.0 && value <= std::numeric_limits<int32_t>::max())
            origin = static_cast<int32_t>(value);
          for (int c = 0; c < 3 && has_colors; ++c)
            if (index == icolor[c]) {
              // Float colours are in [0, 1]; integer ones in [0, 255].
              const double scaled = ply_is_float(property.type) ? 255.0 * value : value;
              color[c] = static_cast<uint8_t>(std::clamp(std::round(scaled), 0.0, 255.0));
            }
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
        if (has_colors) mesh.colors.push_back(color);
        if (iorigin >= 0) mesh.origins.push_back(origin);
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

}  // namespace

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

}  // namespace meshquilt::io
