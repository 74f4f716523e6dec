#pragma once
// Telling texture-space files (`synth --write-texture`) from meshes by name.

#include <string>

namespace meshquilt::cli {

// Whether `path` names a texture-space file (extension .mqt, any case).
bool is_texture_file(const std::string& path);

}  // namespace meshquilt::cli
