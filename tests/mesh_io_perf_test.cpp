// Reading speed on a million-face mesh in every format (labelled slow). The limit is generous so
// the test catches a quadratic or per-token-allocation parser, not machine noise.

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "mesh/mesh_io.h"

namespace meshquilt {
namespace {

namespace fs = std::filesystem;

// A wavy n x n vertex grid: 2 (n-1)^2 triangles.
TriMesh grid(int n) {
  TriMesh m;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) m.positions.push_back(Vec3(i * 0.001, j * 0.001, 0.01 * std::sin(i * 0.1 + j * 0.07)));
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const int v = j * n + i;
      m.triangles.push_back({v, v + 1, v + n + 1});
      m.triangles.push_back({v, v + n + 1, v + n});
      m.elements.push_back(j);
      m.elements.push_back(j);
    }
  }
  return m;
}

TEST(MeshIoPerf, MillionFacesReadQuickly) {
  const TriMesh mesh = grid(709);  // 1,002,528 faces
  ASSERT_GT(mesh.triangles.size(), 1000000u);
  const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
  const fs::path dir = base / ("meshquilt_mesh_io_perf_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct Case {
    const char* name;
    bool binary;
  };
  for (const Case c : {Case{"b.ply", true}, Case{"a.ply", false}, Case{"m.obj", true}, Case{"m.off", true},
                       Case{"b.stl", true}}) {
    const fs::path file = dir / c.name;
    const auto t0 = std::chrono::steady_clock::now();
    write_mesh(mesh, file, WriteOptions{c.binary});
    const auto t1 = std::chrono::steady_clock::now();
    const TriMesh back = read_mesh(file);
    const auto t2 = std::chrono::steady_clock::now();
    const double write_s = std::chrono::duration<double>(t1 - t0).count();
    const double read_s = std::chrono::duration<double>(t2 - t1).count();
    std::printf("%-6s %s: write %.3f s, read %.3f s (%.1f MB)\n", c.name, c.binary ? "binary" : "ascii", write_s,
                read_s, fs::file_size(file) / 1e6);
    EXPECT_EQ(back.triangles.size(), mesh.triangles.size()) << c.name;
    EXPECT_EQ(back.positions.size(), mesh.positions.size()) << c.name;
    EXPECT_LT(read_s, 10.0) << c.name;
    fs::remove(file);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace meshquilt
