#pragma once
//! Output elements from local coordinates into space through an embedding. Synthesis decides on
//! SurfaceEmbedding::position_during_synthesis; where the final map differs from it (the
//! stretch-minimized shell map, computed in float32 on the device), a few elements that the
//! decisions kept apart can meet. Those are placed through the map the decisions were made on,
//! which keeps them apart; the rest through the final map.

#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/tri_mesh.h"
#include "spatial/intersecting_pairs.h"
#include "surface/surface_embedding.h"
#include "surface/surface_quilting.h"

namespace meshquilt {

struct ElementPlacement {
  std::vector<Vec3> positions;                 //!< #V
  std::vector<uint8_t> through_synthesis_map;  //!< per element: placed by position_during_synthesis
  //! The faces that meet at `positions` (face indices as `triangles`), where the last test saw
  //! the final positions.
  std::optional<FaceIntersections> intersections;
  //! The faces that meet with every element placed through the final map (the first test).
  std::optional<FaceIntersections> final_map_intersections;

  //! How many elements went through the synthesis map.
  int moved_elements() const;
};

//! Places `vertices` (#V; each belongs to the element of the faces using it) of the elements
//! `face_element` (#F, ids from 0) names: through embedding.position, then, where the
//! embedding has a distinct synthesis map, every element that passes through another goes through
//! position_during_synthesis instead, repeated while that changes something (at most `rounds`
//! times). Deterministic: the same inputs give the same positions, so `meshquilt embed` over the
//! base a texture was made on reproduces synth. `final_map`, when given, is what the first test
//! would find (final_map_intersections of a placement of more elements, less theirs).
ElementPlacement place_elements(const SurfaceEmbedding& embedding, const std::vector<LocalVertex>& vertices,
                                const std::vector<Tri>& triangles, const std::vector<int32_t>& face_element,
                                int rounds = 4, const FaceIntersections* final_map = nullptr);

}  // namespace meshquilt
