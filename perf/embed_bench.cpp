// Re-embedding against synthesis (Section 3.2 of the mesh quilting paper, last paragraph):
// synthesizes the default chain mail over a base once through the shell map, then re-embeds the
// same texture over the base bent, scaled and rigidly moved (the shell rebuilt over the edited
// base, every output vertex mapped again by the rule synth and embed share) and prints the
// median seconds of each against the synthesis, as a Markdown table.
//
//   embed_bench BASE [--scale S] [--runs N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "device.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_io.h"
#include "surface/element_placement.h"
#include "surface/surface_quilting.h"
#include "shell/shell_embedding.h"
#include "swatch/chainmail.h"

namespace {

using namespace meshquilt;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: embed_bench BASE [--scale S] [--runs N]\n");
    return 2;
  }
  double scale = 0.1;
  int runs = 5;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scale")) scale = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--runs")) runs = std::atoi(argv[i + 1]);
  }
  const TriMesh base = prepare_base(read_mesh(argv[1]), argv[1]);
  const BaseSurface surface(base);
  const GuidanceField field = interpolate_field(surface, {});
  auto device = engine::open_device(engine::BackendChoice::cpu);
  SurfaceQuiltOptions options;
  options.scale = scale;
  ShellTexture texture;
  options.embedding = [&](const BaseSurface& b, double height) {
    auto embedding = build_shell_embedding(*device, b, height);
    texture = embedding->texture();
    return std::unique_ptr<SurfaceEmbedding>(std::move(embedding));
  };
  const auto start = Clock::now();
  const SurfaceQuilt quilt = quilt_surface(make_chainmail(ChainmailOptions{}), base, field, *device, options);
  const double synthesis = seconds_since(start);

  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : base.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const Vec3 centre = 0.5 * (lo + hi);
  const double extent = hi.x - lo.x;
  struct Edit {
    const char* name;
    Vec3 (*apply)(const Vec3&, const Vec3&, double);
  };
  const Edit edits[] = {
      {"bent (30 degrees end to end about y)",
       [](const Vec3& p, const Vec3& c, double e) {
         const double a = 0.5236 * (p.x - c.x) / e;
         const Vec3 q = p - c;
         return c + Vec3(std::cos(a) * q.x + std::sin(a) * q.z, q.y, -std::sin(a) * q.x + std::cos(a) * q.z);
       }},
      {"scaled by 1.3", [](const Vec3& p, const Vec3& c, double) { return c + 1.3 * (p - c); }},
      {"rigidly moved",
       [](const Vec3& p, const Vec3&, double) { return Vec3(p.z, p.x, p.y) + Vec3(1.0, 2.0, 3.0); }},
  };
  std::printf("%s, default chain mail at --scale %g: %zu faces, synthesis %.1f s (one run)\n\n", argv[1],
              scale, quilt.mesh.num_faces(), synthesis);
  std::printf(
      "| edit | re-embedding (s, median of %d) | / synthesis | elements through the original map |\n"
      "|---|---|---|---|\n",
      runs);
  for (const Edit& edit : edits) {
    TriMesh edited = base;
    for (Vec3& p : edited.positions) p = edit.apply(p, centre, extent);
    std::vector<double> times;
    int moved = 0;
    for (int r = 0; r < runs; ++r) {
      const auto t0 = Clock::now();
      const BaseSurface edited_surface(edited);
      const ShellEmbedding embedding(edited_surface, texture, build_shell(edited_surface, texture.height));
      const ElementPlacement placed =
          place_elements(embedding, quilt.local, quilt.mesh.triangles, quilt.mesh.elements);
      times.push_back(seconds_since(t0));
      moved = std::max(moved, placed.moved_elements());
    }
    std::printf("| %s | %.3f | %.4f | %d |\n", edit.name, median(times), median(times) / synthesis, moved);
  }
  return 0;
}
