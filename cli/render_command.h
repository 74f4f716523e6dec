#pragma once
//! `meshquilt render MESH -o OUT.png`: a preview image of a mesh, and the same preview for other
//! commands (`synth --preview`).

#include <filesystem>
#include <string>

#include "mesh/tri_mesh.h"
#include "render/render_mesh.h"

namespace meshquilt::cli {

//! Renders `mesh` (render_mesh) and writes the PNG atomically: a temporary file beside `png`,
//! then a rename, so a failure leaves no file and an existing one untouched.
//! \throw IoError(unknown_format) unless `png` ends in .png (any case); IoError(write_failed)
//!        when its folder is missing or not writable or the write fails; InputError as
//!        render_mesh (no faces, options out of range). Messages name the file or option.
void write_preview(const TriMesh& mesh, const std::filesystem::path& png, const RenderOptions& options = {});

//! Parses `--size WxH` (e.g. 1024x768) into options->width and options->height.
//! \throw InputError(invalid_option) naming --size for another form or a side outside
//!        1..kMaxImageSide.
void parse_image_size(const std::string& text, RenderOptions* options);

}  // namespace meshquilt::cli
