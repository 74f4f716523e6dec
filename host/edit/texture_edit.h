#pragma once
//! Editing a texture-space file (`synth --write-texture`): the same element edits, so an edited
//! texture can still be placed over its base, or over every frame of a moving one.

#include <cstdint>
#include <vector>

#include "shell/texture_file.h"

namespace meshquilt {

//! `texture` with only the faces in `keep` (#F), its vertices renumbered in their old order; the
//! base, shell and atlas stay as they are.
QuiltTexture keep_texture_faces(const QuiltTexture& texture, const std::vector<uint8_t>& keep);

}  // namespace meshquilt
