#include "spatial/near_face_grid_cache.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <system_error>

#include "core/error.h"
#include "core/atomic_write.h"
#include "core/populate_pages.h"

namespace meshquilt {
namespace {

// Bumped whenever build_near_face_grid lists differently, so that files keep the current
// builder's speed (an older grid still gives the same answers), and whenever the layout changes.
constexpr uint32_t kFormat = 1;
constexpr char kMagic[8] = {'M', 'Q', 'G', 'R', 'I', 'D', '\0', '\1'};
constexpr uint32_t kByteOrder = 0x01020304;
constexpr size_t kKeyChars = 32;

// A 64-bit fingerprint of bytes (not cryptographic: it names and checks files the program wrote
// itself). Four lanes of words, each word mixed by MurmurHash3's finalizer, so long arrays hash
// at memory speed.
uint64_t mix(uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return x;
}

uint64_t fingerprint(std::string_view bytes, uint64_t seed) {
  constexpr uint64_t kOdd = 0x9e3779b97f4a7c15ULL;
  uint64_t lane[4] = {seed, seed + kOdd, seed + 2 * kOdd, seed + 3 * kOdd};
  size_t i = 0;
  for (; i + 32 <= bytes.size(); i += 32)
    for (int k = 0; k < 4; ++k) {
      uint64_t w;
      std::memcpy(&w, bytes.data() + i + 8 * k, 8);
      lane[k] = (lane[k] ^ mix(w)) * kOdd;
    }
  uint64_t h = mix(lane[0] ^ mix(lane[1] ^ mix(lane[2] ^ mix(lane[3] ^ bytes.size()))));
  for (; i < bytes.size(); ++i) h = mix(h ^ static_cast<unsigned char>(bytes[i]));
  return h;
}

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
void put_array(std::string& out, const std::vector<T>& values) {
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

template <typename T>
std::string_view bytes_of(const std::vector<T>& values) {
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

// The file: this header, the grid's seven arrays as they lie in memory, and a fingerprint of
// all that.
struct Header {
  char magic[8];
  uint32_t format;
  uint32_t byte_order;
  char key[kKeyChars];
  double origin[3], box_low[3], box_high[3], voxel;
  int32_t size[3];
  uint32_t padding;
  uint64_t entries, groups;
};
static_assert(sizeof(Header) == 160);

uint64_t checksum(std::span<const std::string_view> pieces) {
  uint64_t h = 0;
  for (std::string_view piece : pieces) h = mix(h ^ fingerprint(piece, 3));
  return h;
}

// The pieces of the file but the last (the checksum), the first being `header`.
std::vector<std::string_view> pieces(const NearFaceGrid& grid, std::string_view key, Header& header) {
  header = Header{};
  std::memcpy(header.magic, kMagic, sizeof(kMagic));
  header.format = kFormat;
  header.byte_order = kByteOrder;
  std::memset(header.key, ' ', kKeyChars);
  std::memcpy(header.key, key.data(), std::min(key.size(), kKeyChars));
  for (int k = 0; k < 3; ++k) {
    header.origin[k] = grid.origin[k];
    header.box_low[k] = grid.box_low[k];
    header.box_high[k] = grid.box_high[k];
    header.size[k] = grid.size[k];
  }
  header.voxel = grid.voxel;
  header.entries = grid.faces.size();
  header.groups = grid.groups.size();
  return {std::string_view(reinterpret_cast<const char*>(&header), sizeof(header)),
          bytes_of(grid.start), bytes_of(grid.faces), bytes_of(grid.near), bytes_of(grid.reach),
          bytes_of(grid.nearest_face), bytes_of(grid.group_start), bytes_of(grid.groups)};
}

// Copies `count` values from bytes[at, ...) into `values`, or fails past the end.
template <typename T>
bool take(std::string_view bytes, size_t& at, uint64_t count, std::vector<T>& values, std::string_view& piece) {
  if (count > (bytes.size() - at) / sizeof(T)) return false;
  piece = bytes.substr(at, count * sizeof(T));
  resize_populated(values, count);
  std::memcpy(values.data(), piece.data(), piece.size());
  at += piece.size();
  return true;
}

// A file mapped for reading (its pages come from the page cache in one call, not one fault each).
class MappedFile {
 public:
  explicit MappedFile(const std::filesystem::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    struct stat st {};
    // A file larger than any grid can be (2^18 voxels of 1,024 entries) is not read.
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 && st.st_size <= (off_t{1} << 32)) {
      void* data = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
      if (data != MAP_FAILED) {
        data_ = data;
        size_ = static_cast<size_t>(st.st_size);
      }
    }
    ::close(fd);
  }
  ~MappedFile() {
    if (data_) ::munmap(data_, size_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  void* data_ = nullptr;
  size_t size_ = 0;
};

bool finite_vec(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Offsets that start at 0, never decrease and end at `total`.
bool valid_offsets(const std::vector<uint32_t>& offsets, uint64_t total) {
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != total) return false;
  for (size_t k = 1; k < offsets.size(); ++k)
    if (offsets[k] < offsets[k - 1]) return false;
  return true;
}

// Everything a reader of the grid relies on: the groups of each voxel tile its list in strictly
// increasing labels (so a voxel has at most `labels` of them), each group in increasing near.
bool consistent(const NearFaceGrid& g, size_t faces, uint32_t labels) {
  if (!(g.voxel > 0.0) || !std::isfinite(g.voxel) || !finite_vec(g.origin) || !finite_vec(g.box_low) ||
      !finite_vec(g.box_high))
    return false;
  const size_t voxels = g.reach.size();
  if (!valid_offsets(g.start, g.faces.size()) || !valid_offsets(g.group_start, g.groups.size())) return false;
  for (uint32_t f : g.faces)
    if (f >= faces) return false;
  for (float near : g.near)
    if (!(near >= 0.0f) || !std::isfinite(near)) return false;
  for (double reach : g.reach)
    if (!(reach >= 0.0) || !std::isfinite(reach)) return false;
  for (int32_t f : g.nearest_face)
    if (f < -1 || f >= static_cast<int64_t>(faces)) return false;
  for (size_t v = 0; v < voxels; ++v) {
    uint32_t entry = g.start[v];
    for (uint32_t k = g.group_start[v]; k < g.group_start[v + 1]; ++k) {
      const FaceGroup& group = g.groups[k];
      if (group.first != entry || group.end <= group.first || group.end > g.start[v + 1] || group.label >= labels ||
          (k > g.group_start[v] && group.label <= g.groups[k - 1].label) || group.near != g.near[group.first])
        return false;
      for (uint32_t m = group.first + 1; m < group.end; ++m)
        if (g.near[m] < g.near[m - 1]) return false;
      entry = group.end;
    }
    if (entry != g.start[v + 1]) return false;
  }
  return true;
}

}  // namespace

NearFaceGrid NearFaceGridRequest::build(const TriMesh& mesh) const {
  return build_near_face_grid(mesh, voxel, margin, list_margin, far, max_list, max_voxels, face_groups);
}

const char* to_string(GridSource source) {
  switch (source) {
    case GridSource::built: return "built";
    case GridSource::read: return "read";
    case GridSource::written: return "written";
    case GridSource::unsaved: return "unsaved";
  }
  return "built";
}

std::string near_face_grid_key(const TriMesh& mesh, const NearFaceGridRequest& request) {
  std::string material;
  put(material, kFormat);
  put_array(material, mesh.positions);
  put_array(material, mesh.triangles);
  for (double x : {request.voxel, request.margin, request.list_margin, request.far}) put(material, x);
  put(material, static_cast<int64_t>(request.max_list));
  put(material, request.max_voxels);
  put_array(material, request.face_groups);
  static const char* hex = "0123456789abcdef";
  std::string key;
  for (uint64_t h : {fingerprint(material, 1), fingerprint(material, 2)})
    for (int shift = 60; shift >= 0; shift -= 4) key += hex[(h >> shift) & 15];
  return key;
}

std::string near_face_grid_bytes(const NearFaceGrid& grid, std::string_view key) {
  Header header;
  const std::vector<std::string_view> parts = pieces(grid, key, header);
  std::string out;
  for (std::string_view piece : parts) out.append(piece);
  put(out, checksum(parts));
  return out;
}

std::optional<NearFaceGrid> near_face_grid_from_bytes(std::string_view bytes, std::string_view key, size_t faces,
                                                      uint32_t labels) {
  Header header;
  if (bytes.size() < sizeof(header) + sizeof(uint64_t)) return std::nullopt;
  std::memcpy(&header, bytes.data(), sizeof(header));
  if (std::memcmp(header.magic, kMagic, sizeof(kMagic)) != 0 || header.format != kFormat ||
      header.byte_order != kByteOrder || std::string_view(header.key, kKeyChars) != key)
    return std::nullopt;
  NearFaceGrid grid;
  for (int k = 0; k < 3; ++k) {
    grid.origin[k] = header.origin[k];
    grid.box_low[k] = header.box_low[k];
    grid.box_high[k] = header.box_high[k];
    grid.size[k] = header.size[k];
  }
  grid.voxel = header.voxel;
  if (grid.size.x < 1 || grid.size.y < 1 || grid.size.z < 1) return std::nullopt;
  const uint64_t voxels = static_cast<uint64_t>(grid.size.x) * grid.size.y * grid.size.z;
  if (voxels > bytes.size()) return std::nullopt;
  std::string_view parts[8] = {bytes.substr(0, sizeof(header))};
  size_t at = sizeof(header);
  if (!take(bytes, at, voxels + 1, grid.start, parts[1]) || !take(bytes, at, header.entries, grid.faces, parts[2]) ||
      !take(bytes, at, header.entries, grid.near, parts[3]) || !take(bytes, at, voxels, grid.reach, parts[4]) ||
      !take(bytes, at, voxels, grid.nearest_face, parts[5]) || !take(bytes, at, voxels + 1, grid.group_start, parts[6]) ||
      !take(bytes, at, header.groups, grid.groups, parts[7]) || bytes.size() - at != sizeof(uint64_t))
    return std::nullopt;
  uint64_t stored;
  std::memcpy(&stored, bytes.data() + at, sizeof(stored));
  if (stored != checksum(parts) || !consistent(grid, faces, labels)) return std::nullopt;
  return grid;
}

NearFaceGrid cached_near_face_grid(const std::filesystem::path& folder, const TriMesh& mesh,
                                   const NearFaceGridRequest& request, GridSource* source, int kept_files) {
  namespace fs = std::filesystem;
  const auto report = [&](GridSource s) {
    if (source) *source = s;
  };
  if (folder.empty()) {
    report(GridSource::built);
    return request.build(mesh);
  }
  const std::string key = near_face_grid_key(mesh, request);
  const fs::path file = folder / (key + ".grid");
  const uint32_t labels =
      request.face_groups.empty() ? 1u : *std::max_element(request.face_groups.begin(), request.face_groups.end()) + 1;
  std::error_code error;
  {
    const MappedFile mapped(file);
    if (std::optional<NearFaceGrid> grid = near_face_grid_from_bytes(mapped.bytes(), key, mesh.num_faces(), labels)) {
      fs::last_write_time(file, fs::file_time_type::clock::now(), error);  // recently used
      report(GridSource::read);
      return std::move(*grid);
    }
  }
  NearFaceGrid grid = request.build(mesh);
  fs::create_directories(folder, error);
  try {
    Header header;
    std::vector<std::string_view> parts = pieces(grid, key, header);
    const uint64_t sum = checksum(parts);
    parts.emplace_back(reinterpret_cast<const char*>(&sum), sizeof(sum));
    write_file_atomic(file, parts);
  } catch (const IoError&) {
    report(GridSource::unsaved);
    return grid;
  }
  report(GridSource::written);
  // The least recently used files go first once there are more than kept_files.
  std::vector<std::pair<fs::file_time_type, fs::path>> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (entry.path().extension() == ".grid") files.emplace_back(entry.last_write_time(error), entry.path());
  std::sort(files.begin(), files.end());
  for (size_t k = 0; k + static_cast<size_t>(std::max(kept_files, 1)) < files.size(); ++k)
    if (files[k].second != file) fs::remove(files[k].second, error);
  return grid;
}

}  // namespace meshquilt
