#include "shell/texture_file.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"
#include "core/atomic_write.h"

namespace meshquilt {
namespace {

constexpr char kMagic[] = "MQTEXTURE2\n";
constexpr char kMagicVersion1[] = "MQTEXTURE1\n";  // read still: no origins
constexpr size_t kMagicBytes = sizeof(kMagic) - 1;

uint64_t fnv1a(const void* data, size_t bytes, uint64_t hash = 0xcbf29ce484222325ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
  return hash;
}

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const auto* p = reinterpret_cast<const char*>(&value);
    bytes_.append(p, sizeof(T));
  }
  template <class T>
  void put_all(const std::vector<T>& values) {
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void raw(const char* p, size_t n) { bytes_.append(p, n); }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}
  template <class T>
  T get() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  template <class T>
  std::vector<T> get_all(size_t count) {
    if (count > (bytes_.size() - at_) / sizeof(T)) fail("truncated (ends inside its arrays)");
    std::vector<T> values(count);
    if (count > 0) std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
    at_ += count * sizeof(T);
    return values;
  }
  size_t at() const { return at_; }
  //! Fails unless `count` items of `bytes` each are left, before anything is allocated for them.
  void expect_items(size_t count, size_t bytes) const {
    if (count > (bytes_.size() - at_) / bytes) fail("truncated (ends inside its arrays)");
  }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(name_ + ": " + problem, ErrorKind::bad_texture);
  }

 private:
  void need(size_t n) const {
    if (bytes_.size() - at_ < n) fail("truncated");
  }
  const std::string& bytes_;
  std::string name_;
  size_t at_ = 0;
};

}  // namespace

uint64_t connectivity_hash(const TriMesh& base) {
  return fnv1a(base.triangles.data(), base.triangles.size() * sizeof(Tri));
}

QuiltTexture make_quilt_texture(const TriMesh& base, const TriMesh& mesh,
                                const std::vector<LocalVertex>& local, const ShellTexture& shell) {
  QuiltTexture t;
  t.base_vertices = static_cast<uint32_t>(base.num_vertices());
  t.base_faces = static_cast<uint32_t>(base.num_faces());
  t.base_connectivity = connectivity_hash(base);
  t.shell = shell;
  t.vertices = local;
  t.triangles = mesh.triangles;
  t.elements = mesh.elements;
  t.sources = mesh.sources;
  t.origins = mesh.origins;
  return t;
}

std::string format_texture(const QuiltTexture& t) {
  Writer w;
  w.raw(kMagic, kMagicBytes);
  w.put(t.base_vertices);
  w.put(t.base_faces);
  w.put(t.base_connectivity);
  const bool shell = t.shell.height > 0.0 && !t.shell.atlas.face_chart.empty();
  w.put(shell ? t.shell.height : 0.0);
  const TextureAtlas& atlas = t.shell.atlas;
  w.put(static_cast<uint32_t>(shell ? atlas.charts : 0));
  w.put(static_cast<uint32_t>(shell ? atlas.uv.size() : 0));
  w.put(static_cast<uint32_t>(t.vertices.size()));
  w.put(static_cast<uint32_t>(t.triangles.size()));
  if (shell) {
    w.put_all(atlas.face_chart);
    w.put_all(atlas.corners);
    w.put_all(atlas.vertex_base);
    w.put_all(atlas.vertex_chart);
    w.put_all(atlas.uv);
    w.put_all(atlas.on_boundary);
    w.put_all(t.shell.top_uv);
  }
  for (const LocalVertex& v : t.vertices) {
    w.put(v.point.face);
    w.put(v.point.bary.x);
    w.put(v.point.bary.y);
    w.put(v.height);
  }
  w.put_all(t.triangles);
  std::vector<int32_t> elements = t.elements, sources = t.sources;
  elements.resize(t.triangles.size(), 0);
  sources.resize(t.triangles.size(), -1);
  w.put_all(elements);
  w.put_all(sources);
  std::vector<int32_t> origins = t.origins;
  origins.resize(t.vertices.size(), -1);
  w.put_all(origins);
  w.put(fnv1a(w.bytes().data(), w.bytes().size()));
  return std::move(w.bytes());
}

void write_texture_file(const std::filesystem::path& file, const QuiltTexture& texture) {
  write_file_atomic(file, format_texture(texture));
}

QuiltTexture read_texture_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ErrorKind::file_unreadable, file.string() + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_texture(bytes, file.string());
}

QuiltTexture parse_texture(const std::string& bytes, const std::string& name) {
  Reader r(bytes, name);
  const bool version2 = bytes.size() >= kMagicBytes && bytes.compare(0, kMagicBytes, kMagic) == 0;
  if (!version2 && (bytes.size() < kMagicBytes || bytes.compare(0, kMagicBytes, kMagicVersion1) != 0))
    r.fail("not a meshquilt texture file (no MQTEXTURE2 or MQTEXTURE1 header)");
  if (bytes.size() < kMagicBytes + 8) r.fail("truncated");
  uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  const bool intact = fnv1a(bytes.data(), bytes.size() - 8) == stored;
  r.get_all<char>(kMagicBytes);

  QuiltTexture t;
  t.base_vertices = r.get<uint32_t>();
  t.base_faces = r.get<uint32_t>();
  t.base_connectivity = r.get<uint64_t>();
  t.shell.height = r.get<double>();
  const uint32_t charts = r.get<uint32_t>(), atlas_vertices = r.get<uint32_t>();
  const uint32_t vertices = r.get<uint32_t>(), faces = r.get<uint32_t>();
  if (!std::isfinite(t.shell.height) || t.shell.height < 0.0) r.fail("bad shell height");
  if (t.shell.height > 0.0) {
    TextureAtlas& atlas = t.shell.atlas;
    atlas.charts = static_cast<int32_t>(charts);
    atlas.face_chart = r.get_all<int32_t>(t.base_faces);
    atlas.corners = r.get_all<std::array<int32_t, 3>>(t.base_faces);
    atlas.vertex_base = r.get_all<int32_t>(atlas_vertices);
    atlas.vertex_chart = r.get_all<int32_t>(atlas_vertices);
    atlas.uv = r.get_all<glm::dvec2>(atlas_vertices);
    atlas.on_boundary = r.get_all<uint8_t>(atlas_vertices);
    t.shell.top_uv = r.get_all<glm::dvec2>(atlas_vertices);
  }
  r.expect_items(vertices, sizeof(int32_t) + 3 * sizeof(double));
  t.vertices.resize(vertices);
  for (LocalVertex& v : t.vertices) {
    v.point.face = r.get<int32_t>();
    v.point.bary.x = r.get<double>();
    v.point.bary.y = r.get<double>();
    v.height = r.get<double>();
  }
  t.triangles = r.get_all<Tri>(faces);
  t.elements = r.get_all<int32_t>(faces);
  t.sources = r.get_all<int32_t>(faces);
  if (version2) t.origins = r.get_all<int32_t>(vertices);
  if (r.at() + 8 != bytes.size()) r.fail(r.at() + 8 < bytes.size() ? "trailing bytes" : "truncated");
  if (!intact) r.fail("checksum mismatch (corrupt or truncated)");

  // Indices and values, so that nothing downstream reads out of range.
  const TextureAtlas& atlas = t.shell.atlas;
  for (size_t f = 0; f < atlas.face_chart.size(); ++f) {
    if (atlas.face_chart[f] < 0 || atlas.face_chart[f] >= atlas.charts) r.fail("atlas chart out of range");
    for (int32_t a : atlas.corners[f])
      if (a < 0 || static_cast<uint32_t>(a) >= atlas_vertices) r.fail("atlas corner out of range");
  }
  for (size_t a = 0; a < atlas_vertices; ++a) {
    if (atlas.vertex_base[a] < 0 || static_cast<uint32_t>(atlas.vertex_base[a]) >= t.base_vertices)
      r.fail("atlas vertex out of range");
    if (!std::isfinite(atlas.uv[a].x + atlas.uv[a].y + t.shell.top_uv[a].x + t.shell.top_uv[a].y))
      r.fail("atlas coordinate not finite");
  }
  for (const LocalVertex& v : t.vertices) {
    if (v.point.face < 0 || static_cast<uint32_t>(v.point.face) >= t.base_faces)
      r.fail("vertex face out of range");
    if (!std::isfinite(v.point.bary.x + v.point.bary.y + v.height)) r.fail("vertex coordinate not finite");
  }
  for (const Tri& tri : t.triangles)
    for (int32_t v : tri)
      if (v < 0 || static_cast<uint32_t>(v) >= vertices) r.fail("face index out of range");
  for (int32_t o : t.origins)
    if (o < -1) r.fail("vertex origin out of range");
  return t;
}

void check_texture_base(const QuiltTexture& texture, const TriMesh& base, const std::string& base_name) {
  if (base.num_faces() != texture.base_faces || base.num_vertices() != texture.base_vertices)
    throw InputError(base_name + ": has " + std::to_string(base.num_vertices()) + " vertices and " +
                         std::to_string(base.num_faces()) + " faces; the texture was made over " +
                         std::to_string(texture.base_vertices) + " and " + std::to_string(texture.base_faces),
                     ErrorKind::base_mismatch);
  if (connectivity_hash(base) != texture.base_connectivity)
    throw InputError(base_name + ": its faces connect other vertices than the base the texture was made over",
                     ErrorKind::base_mismatch);
}

}  // namespace meshquilt
