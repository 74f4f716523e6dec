#include "shell/texture_placement.h"

#include <memory>

#include "core/error.h"
#include "surface/element_placement.h"

namespace meshquilt {


PlacedTexture place_texture(const QuiltTexture& texture, const TriMesh& base, const std::string& embed,
                            const std::string& texture_name) {
  if (embed != "auto" && embed != "shell" && embed != "normal")
    throw InputError("{embed}: expected auto, shell or normal, got '" + embed + "'",
                     ErrorKind::invalid_option);
  if (embed == "shell" && texture.shell.height <= 0.0)
    throw InputError(texture_name + ": written with {embed} normal, so it holds no shell map",
                     ErrorKind::invalid_option);
  PlacedTexture placed;
  const BaseSurface surface(base);
  std::unique_ptr<SurfaceEmbedding> embedding;
  placed.shell_map = texture.shell.height > 0.0 && embed != "normal";
  if (placed.shell_map) {
    auto shell =
        std::make_unique<ShellEmbedding>(surface, texture.shell, build_shell(surface, texture.shell.height));
    placed.shell_reduced_vertices = shell->map().shell().reduced_vertices;
    embedding = std::move(shell);
  } else {
    embedding = std::make_unique<NormalEmbedding>(surface);
  }
  // The rule synth placed its elements by, so that the same base gives the same output.
  ElementPlacement placement =
      place_elements(*embedding, texture.vertices, texture.triangles, texture.elements);
  placed.synthesis_map_elements = placement.moved_elements();
  placed.mesh.positions = std::move(placement.positions);
  placed.mesh.triangles = texture.triangles;
  placed.mesh.elements = texture.elements;
  placed.mesh.sources = texture.sources;
  placed.mesh.origins = texture.origins;
  return placed;
}

}  // namespace meshquilt
