#include "edit/texture_edit.h"

namespace meshquilt {

QuiltTexture keep_texture_faces(const QuiltTexture& texture, const std::vector<uint8_t>& keep) {
  QuiltTexture out;
  out.base_vertices = texture.base_vertices;
  out.base_faces = texture.base_faces;
  out.base_connectivity = texture.base_connectivity;
  out.shell = texture.shell;
  std::vector<int32_t> index(texture.vertices.size(), -1);
  for (size_t f = 0; f < texture.triangles.size(); ++f)
    if (keep[f])
      for (int32_t v : texture.triangles[f]) index[v] = 0;
  for (size_t v = 0; v < texture.vertices.size(); ++v) {
    if (index[v] < 0) continue;
    index[v] = static_cast<int32_t>(out.vertices.size());
    out.vertices.push_back(texture.vertices[v]);
    if (!texture.origins.empty()) out.origins.push_back(texture.origins[v]);
  }
  for (size_t f = 0; f < texture.triangles.size(); ++f) {
    if (!keep[f]) continue;
    const Tri& t = texture.triangles[f];
    out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    out.elements.push_back(texture.elements[f]);
    out.sources.push_back(texture.sources[f]);
  }
  return out;
}

}  // namespace meshquilt
