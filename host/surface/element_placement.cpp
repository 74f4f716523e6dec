#include "surface/element_placement.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "spatial/intersecting_pairs.h"

namespace meshquilt {

int ElementPlacement::moved_elements() const {
  return static_cast<int>(std::count(through_synthesis_map.begin(), through_synthesis_map.end(), 1));
}

ElementPlacement place_elements(const SurfaceEmbedding& embedding, const std::vector<LocalVertex>& vertices,
                                const std::vector<Tri>& triangles, const std::vector<int32_t>& face_element,
                                int rounds, const FaceIntersections* final_map) {
  ElementPlacement out;
  const int32_t last = face_element.empty() ? -1 : *std::max_element(face_element.begin(), face_element.end());
  out.through_synthesis_map.assign(static_cast<size_t>(last + 1), 0);
  TriMesh mesh;
  mesh.triangles = triangles;
  // Each vertex is placed on its own: side by side, into its own slot.
  mesh.positions.resize(vertices.size());
  tbb::parallel_for(size_t{0}, vertices.size(),
                    [&](size_t v) { mesh.positions[v] = embedding.position(vertices[v].point, vertices[v].height); });
  if (embedding.has_synthesis_map()) {
    std::vector<int32_t> vertex_element(vertices.size(), -1);
    for (size_t f = 0; f < triangles.size(); ++f)
      for (int32_t v : triangles[f]) vertex_element[v] = face_element[f];
    FaceIntersections found = final_map ? *final_map : find_intersecting_faces(mesh, face_element);
    out.final_map_intersections = found;
    for (int round = 0; round < rounds; ++round) {
      std::vector<uint8_t> moving(out.through_synthesis_map.size(), 0);
      bool any = false;
      for (const auto& [a, b] : found.different_elements)
        for (const int32_t e : {face_element[a], face_element[b]})
          if (!out.through_synthesis_map[e]) {
            moving[e] = out.through_synthesis_map[e] = 1;
            any = true;
          }
      if (!any) {
        out.intersections = std::move(found);
        break;
      }
      tbb::parallel_for(size_t{0}, vertices.size(), [&](size_t v) {
        if (vertex_element[v] >= 0 && moving[vertex_element[v]])
          mesh.positions[v] = embedding.position_during_synthesis(vertices[v].point, vertices[v].height);
      });
      // Only the moved elements' faces changed.
      if (round + 1 < rounds) found = find_intersecting_faces_again(mesh, face_element, found, moving);
    }
  }
  out.positions = std::move(mesh.positions);
  return out;
}

}  // namespace meshquilt
