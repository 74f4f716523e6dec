// Honest limits in the readers: headers that declare more than the file can hold or than the
// memory budget allows are refused with a one-line error before anything large is allocated.
// The allocation bound is measured by counting every operator new of this test executable.
#include <gtest/gtest.h>

#include <optional>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"
#include "mesh/mesh_io.h"
#include "swatch/netpbm.h"

#if defined(__SANITIZE_ADDRESS__)
#define MESHQUILT_COUNT_ALLOCATIONS 0  // the sanitizer owns operator new there
#else
#define MESHQUILT_COUNT_ALLOCATIONS 1
#endif

namespace {
std::atomic<size_t> g_live{0};
std::atomic<size_t> g_peak{0};
}  // namespace

#if MESHQUILT_COUNT_ALLOCATIONS
// Each block carries its size in a 16-byte header so delete can subtract it.
void* operator new(size_t size) {
  void* block = std::malloc(size + 16);
  if (!block) throw std::bad_alloc();
  *static_cast<size_t*>(block) = size;
  const size_t live = g_live.fetch_add(size) + size;
  size_t peak = g_peak.load();
  while (live > peak && !g_peak.compare_exchange_weak(peak, live)) {
  }
  return static_cast<char*>(block) + 16;
}
void* operator new[](size_t size) { return operator new(size); }
void operator delete(void* p) noexcept {
  if (!p) return;
  void* block = static_cast<char*>(p) - 16;
  g_live.fetch_sub(*static_cast<size_t*>(block));
  std::free(block);
}
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, size_t) noexcept { operator delete(p); }
void operator delete[](void* p, size_t) noexcept { operator delete(p); }
#endif

namespace meshquilt {
namespace {

constexpr size_t kAllocationBound = 4u << 20;  // "a few MB"

struct Refusal {
  std::optional<ErrorKind> code;
  std::string message;
  size_t peak_bytes = 0;  // most bytes live at once during the call, above what was live before
};

template <typename F>
Refusal refusal(F&& call) {
  Refusal r;
  g_peak.store(g_live.load());
  const size_t before = g_live.load();
  try {
    call();
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    r.code = e.kind();
    r.message = e.what();
  }
  r.peak_bytes = g_peak.load() - before;
  return r;
}

void expect_refused(const Refusal& r, ErrorKind code, const std::string& needle) {
  EXPECT_EQ(r.code, code) << r.message;
  EXPECT_NE(r.message.find(needle), std::string::npos) << r.message;
  EXPECT_EQ(r.message.find('\n'), std::string::npos) << r.message;
#if MESHQUILT_COUNT_ALLOCATIONS
  EXPECT_LT(r.peak_bytes, kAllocationBound) << r.message;
#endif
}

// A 1 KB PLY file whose header declares 2^31 faces.
std::string huge_face_ply(const char* format) {
  std::string text = std::string("ply\nformat ") + format +
                     " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 2147483648\nproperty list uchar int vertex_indices\nend_header\n";
  text.resize(1024, ' ');
  return text;
}

TEST(ReaderLimits, PlyAsciiHeaderDeclaringTwoToThe31Faces) {
  const std::string data = huge_face_ply("ascii");
  expect_refused(refusal([&] { parse_mesh(data, ".ply", "huge.ply"); }), ErrorKind::invalid_mesh,
                 "huge.ply: PLY header declares 2147483648 'face' items");
}

TEST(ReaderLimits, PlyBinaryHeaderDeclaringTwoToThe31Faces) {
  const std::string data = huge_face_ply("binary_little_endian");
  expect_refused(refusal([&] { parse_mesh(data, ".ply", "huge.ply"); }), ErrorKind::invalid_mesh,
                 "more than the");
}

TEST(ReaderLimits, PlyElementWithoutPropertiesAndAHugeCount) {
  // Items without properties take no bytes: without a limit this loops 2^62 times.
  const std::string data =
      "ply\nformat binary_little_endian 1.0\nelement nothing 4611686018427387904\nend_header\n";
  expect_refused(refusal([&] { parse_mesh(data, ".ply", "empty.ply"); }), ErrorKind::invalid_mesh, "4611686018427387904");
}

TEST(ReaderLimits, ObjFaceIndexTwoToThe40) {
  const std::string data = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1099511627776\n";
  expect_refused(refusal([&] { parse_mesh(data, ".obj", "big.obj"); }), ErrorKind::invalid_mesh,
                 "big.obj: line 4: face index 1099511627776 out of range");
}

TEST(ReaderLimits, OffNegativeCount) {
  const std::string data = "OFF\n-5 1 0\n0 0 0\n";
  expect_refused(refusal([&] { parse_mesh(data, ".off", "neg.off"); }), ErrorKind::invalid_mesh,
                 "neg.off: line 2: bad vertex count '-5'");
}

TEST(ReaderLimits, OffCountsBeyondTheFile) {
  const std::string data = "OFF\n2000000000 2000000000 0\n0 0 0\n";
  expect_refused(refusal([&] { parse_mesh(data, ".off", "big.off"); }), ErrorKind::invalid_mesh,
                 "OFF header declares 2000000000 vertices");
}

TEST(ReaderLimits, StlBinaryCountBeyondTheFile) {
  std::string data(84, '\0');
  const uint32_t count = 0x7FFFFFFF;
  std::memcpy(data.data() + 80, &count, 4);
  data.resize(200, '\0');
  expect_refused(refusal([&] { parse_mesh(data, ".stl", "big.stl"); }), ErrorKind::invalid_mesh,
                 "binary STL size does not match");
}

TEST(ReaderLimits, NetpbmHeaderDeclaringAGigapixel) {
  expect_refused(refusal([&] { parse_netpbm("P5\n32768 32768\n255\n\x01\x02", "big.pgm"); }),
                 ErrorKind::file_unreadable, "big.pgm: header declares 32768 x 32768 pixels");
  expect_refused(refusal([&] { parse_netpbm("P1\n32768 32768\n0101", "big.pbm"); }), ErrorKind::file_unreadable,
                 "declares 32768 x 32768");
  expect_refused(refusal([&] { parse_netpbm("P4\n32768 32768\n\x01", "big.pbm"); }), ErrorKind::file_unreadable,
                 "declares 32768 x 32768");
}

TEST(ReaderLimits, MeshBeyondTheMemoryBudget) {
  // A genuine 2,000-vertex binary PLY, read under a 16 KiB budget.
  std::string data =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2000\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  data.append(2000 * 24, '\0');
  data += '\3';
  data.append(12, '\0');
  set_memory_budget(16 * 1024);
  const Refusal r = refusal([&] { parse_mesh(data, ".ply", "budget.ply"); });
  set_memory_budget(0);
  expect_refused(r, ErrorKind::too_large, "raise it with max_memory");
  EXPECT_NO_THROW(parse_mesh(data, ".ply", "budget.ply"));
}

TEST(MemoryBudget, ParsesSizes) {
  EXPECT_EQ(parse_memory_size("2G"), uint64_t{2} << 30);
  EXPECT_EQ(parse_memory_size("512M"), uint64_t{512} << 20);
  EXPECT_EQ(parse_memory_size("1.5GiB"), uint64_t{3} << 29);
  EXPECT_EQ(parse_memory_size("800k"), 800u * 1024u);
  EXPECT_EQ(parse_memory_size("4096"), 4096u);
  for (const char* bad : {"", "abc", "-1G", "0", "5X", "1e30G"}) {
    try {
      parse_memory_size(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_option);
      EXPECT_NE(e.text().find("{max_memory}"), std::string::npos);  // the CLI names it --max-memory
    }
  }
}

TEST(MemoryBudget, DefaultIsAShareOfWhatTheProcessMayUse) {
  EXPECT_GT(memory_limit_bytes(), uint64_t{64} << 20);
  EXPECT_EQ(default_memory_budget(), memory_limit_bytes() / 4 * 3);
  set_memory_budget(12345);
  EXPECT_EQ(memory_budget(), 12345u);
  set_memory_budget(0);
  EXPECT_EQ(memory_budget(), default_memory_budget());
}

}  // namespace
}  // namespace meshquilt
