#pragma once
//! Editing a synthesized texture element by element (Figure 9 of the mesh quilting paper: a
//! result recoloured and aged by removing a few elements). Elements keep their ids: removing some
//! leaves every other one exactly as it was.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! An axis-aligned box or a sphere; an element is inside when the mean of its vertices is.
struct EditRegion {
  enum class Kind { box, sphere } kind = Kind::box;
  Vec3 lo{0.0}, hi{0.0};  //!< box corners
  Vec3 centre{0.0};       //!< sphere
  double radius = 0.0;
  bool contains(const Vec3& p) const;
};

//! What to remove, applied in this order; each later rule sees only what earlier ones kept.
struct EditRequest {
  std::vector<int32_t> remove_elements;  //!< element ids
  std::vector<int32_t> remove_sources;   //!< swatch elements: every output element copied from one
  std::vector<int32_t> keep_sources;     //!< when not empty: elements of these sources only
  std::vector<EditRegion> remove_inside;
  double age = 0.0;   //!< share of the input's elements removed at random (the paper's aging)
  uint64_t seed = 1;  //!< of the random choice
};

//! How many elements each rule removed.
struct EditCounts {
  int elements = 0;  //!< in the input
  int by_id = 0, by_source = 0, by_keep_source = 0, inside = 0, aged = 0;
  int kept = 0;
};

//! The element of each face and the source of each face, and where each element lies.
struct ElementView {
  std::vector<int32_t> face_elements;  //!< #F
  std::vector<int32_t> face_sources;   //!< #F, or empty
  std::vector<Vec3> positions;         //!< #V, to place elements for remove_inside; may be empty
  std::vector<Tri> triangles;          //!< #F
};

//! The sorted ids of the elements to remove. An element's source is that of its first face.
//! \throw InputError(invalid_option) for an age outside [0, 1], regions without positions, an
//!        empty box or a negative radius.
std::vector<int32_t> elements_to_remove(const ElementView& view, const EditRequest& request,
                                        EditCounts& counts);

//! Which faces stay (#F) when `removed` (sorted ids) go.
std::vector<uint8_t> faces_kept(const std::vector<int32_t>& face_elements,
                                const std::vector<int32_t>& removed);

//! `mesh` with only the faces in `keep`, its vertices renumbered in their old order; elements,
//! sources, colours and origins follow.
TriMesh keep_faces(const TriMesh& mesh, const std::vector<uint8_t>& keep);

//! What to colour by.
enum class ColorBy { element, source };

//! Vertex colours: each vertex takes the palette entry of its first face's element id or source,
//! cycling (id modulo the palette's size); an empty palette means render's element colours.
//! \throw InputError(invalid_option) when colouring by source a mesh without sources.
std::vector<std::array<uint8_t, 3>> vertex_colors(const TriMesh& mesh, ColorBy by,
                                                  const std::vector<std::array<uint8_t, 3>>& palette);

//! Parses "RRGGBB,RRGGBB,..." (a leading '#' allowed). \throw InputError(invalid_option).
std::vector<std::array<uint8_t, 3>> parse_palette(const std::string& text);

}  // namespace meshquilt
