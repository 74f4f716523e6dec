// Writing and reading speed on a million-face mesh in every format, median of --runs (default 3):
//   build/perf/mesh_io_bench [--runs N]
// Exits 1 when a file does not read back with the faces and vertices written.

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

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

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int run(int runs) {
  const TriMesh mesh = grid(709);  // 1,002,528 faces
  const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
  const fs::path dir = base / ("meshquilt_mesh_io_bench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct Case {
    const char* name;
    bool binary;
  };
  int status = 0;
  for (const Case c : {Case{"b.ply", true}, Case{"a.ply", false}, Case{"m.obj", true}, Case{"m.off", true},
                       Case{"b.stl", true}}) {
    const fs::path file = dir / c.name;
    std::vector<double> writes, reads;
    for (int r = 0; r < runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      write_mesh(mesh, file, WriteOptions{c.binary});
      const auto t1 = std::chrono::steady_clock::now();
      const TriMesh back = read_mesh(file);
      const auto t2 = std::chrono::steady_clock::now();
      writes.push_back(std::chrono::duration<double>(t1 - t0).count());
      reads.push_back(std::chrono::duration<double>(t2 - t1).count());
      if (back.triangles.size() != mesh.triangles.size() || back.positions.size() != mesh.positions.size()) {
        std::fprintf(stderr, "%s: read %zu faces, %zu vertices back\n", c.name, back.triangles.size(),
                     back.positions.size());
        status = 1;
      }
    }
    std::printf("%-6s %-6s write %.3f s, read %.3f s (medians of %d; %.1f MB)\n", c.name,
                c.binary ? "binary" : "ascii", median(writes), median(reads), runs, fs::file_size(file) / 1e6);
    fs::remove(file);
  }
  fs::remove_all(dir);
  return status;
}

}  // namespace
}  // namespace meshquilt

int main(int argc, char** argv) {
  int runs = 3;
  if (argc == 3 && std::strcmp(argv[1], "--runs") == 0) runs = std::max(1, std::atoi(argv[2]));
  return meshquilt::run(runs);
}
