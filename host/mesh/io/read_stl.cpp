//! Reading STL, ASCII and binary; exact duplicate vertices are shared.

#include "mesh/io/formats.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "mesh/io/io_helpers.h"

namespace meshquilt::io {
namespace {

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

}  // namespace

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

}  // namespace meshquilt::io
