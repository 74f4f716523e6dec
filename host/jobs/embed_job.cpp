#include "jobs/embed_job.h"

namespace meshquilt {

PlacedTexture run_embed(const QuiltTexture& texture, const TriMesh& base, const std::string& embed,
                        const std::string& texture_name, const std::string& base_name) {
  check_texture_base(texture, base, base_name);
  return place_texture(texture, base, embed, texture_name);
}

nlohmann::json embed_stats(const PlacedTexture& placed) {
  return {{"faces", placed.mesh.num_faces()},
          {"vertices", placed.mesh.num_vertices()},
          {"embed", placed.shell_map ? "shell" : "normal"},
          {"shell_reduced_vertices", placed.shell_reduced_vertices},
          {"synthesis_map_elements", placed.synthesis_map_elements}};
}

}  // namespace meshquilt
