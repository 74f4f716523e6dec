#pragma once
//! An embed as every front end runs it (the CLI, its --base-frames and the Python module): the
//! texture checked against the base, placed, and the stats JSON of `embed --stats`.

#include <string>

#include <nlohmann/json.hpp>

#include "mesh/tri_mesh.h"
#include "shell/texture_file.h"
#include "shell/texture_placement.h"

namespace meshquilt {

//! `texture` placed over `base` (prepared with prepare_base) by `embed` (auto, shell or normal).
//! \throw InputError naming `base_name` when the base is not the one the texture was made over;
//!        see place_texture.
PlacedTexture run_embed(const QuiltTexture& texture, const TriMesh& base, const std::string& embed,
                        const std::string& texture_name, const std::string& base_name);

//! The figures of a placement, as `embed --stats` writes them (less the file names and seconds).
nlohmann::json embed_stats(const PlacedTexture& placed);

}  // namespace meshquilt
