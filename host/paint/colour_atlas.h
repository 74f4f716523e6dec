#pragma once
//! Vertex colours of a refined base baked into a texture of the base itself: the base's texture
//! atlas (the shell's charts, conformal disks) packed into one square image, and each face of
//! the refined mesh drawn into it with its corners' colours blended across it. What `paint
//! --atlas N` writes: the light base with UVs and an image, instead of the refined mesh.

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"
#include "render/rgb_image.h"

namespace meshquilt {

struct ColourAtlas {
  RgbImage image;                                  //!< size x size
  std::vector<std::array<glm::vec2, 3>> face_uv;  //!< #F of the base: its corners in the image, in [0, 1], v down
  int charts = 0;
  double texels_per_unit = 0.0;                    //!< the packing's scale: texels per base unit
};

//! Bakes `refined` (split_faces(base, levels), with a colour per vertex) into a size x size image
//! over `base`'s atlas. Charts keep a gutter of 2 texels, filled outwards from their borders so
//! that filtering does not bleed across them.
//! \throw InputError(invalid_option) for a size outside 16..16384, for a refined mesh that is not
//!        the base split `levels` times with colours, or when the charts do not fit the image;
//!        SolverError from the atlas.
ColourAtlas bake_colour_atlas(const TriMesh& base, const TriMesh& refined, int levels, int size);

}  // namespace meshquilt
