#include "shell/shell_embedding.h"

#include <chrono>

#include "shell/stretch_metric.h"

namespace meshquilt {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ShellEmbedding::ShellEmbedding(const BaseSurface& base, ShellTexture texture, Shell shell)
    : texture_(std::move(texture)),
      shell_(std::move(shell)),
      map_(base, texture_.atlas, shell_, texture_.top_uv),
      original_(base, texture_.atlas, shell_, texture_.atlas.uv) {}

std::unique_ptr<ShellEmbedding> build_shell_embedding(engine::Device& device, const BaseSurface& base,
                                                      double height, const ShellEmbeddingOptions& options,
                                                      ShellReport* report) {
  ShellReport r;
  auto start = std::chrono::steady_clock::now();
  ShellTexture texture;
  texture.atlas = build_texture_atlas(base, options.atlas);
  texture.height = height;
  r.charts = texture.atlas.charts;
  r.seconds_atlas = seconds_since(start);

  start = std::chrono::steady_clock::now();
  Shell shell = build_shell(base, height, options.shell);
  r.reduced_vertices = shell.reduced_vertices;
  r.invalid_prisms = shell.invalid_prisms;
  r.offset_intersections = shell.offset_intersections;
  r.seconds_shell = seconds_since(start);

  start = std::chrono::steady_clock::now();
  r.stretch_initial = measure_stretch(ShellMap(base, texture.atlas, shell, texture.atlas.uv)).l2;
  texture.top_uv = options.minimize_stretch
                       ? minimize_stretch(device, base, texture.atlas, shell, options.stretch)
                       : texture.atlas.uv;
  r.seconds_stretch = seconds_since(start);

  auto embedding = std::make_unique<ShellEmbedding>(base, std::move(texture), std::move(shell));
  r.stretch_final = measure_stretch(embedding->map()).l2;
  r.tets = embedding->map().tet_count();
  if (report) *report = r;
  return embedding;
}

}  // namespace meshquilt
