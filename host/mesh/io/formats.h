#pragma once
//! Internal: the per-format readers and writers behind read_mesh, parse_mesh and write_mesh
//! (mesh_io.h), one pair per format in mesh/io/.

#include <string>
#include <string_view>

#include "mesh/mesh_io.h"
#include "mesh/tri_mesh.h"

namespace meshquilt::io {

// Readers parse a whole file already in memory; `name` prefixes error messages ("FILE: problem").
// They throw InputError (invalid_mesh, too_large) as read_mesh documents; validate_mesh runs after.
TriMesh read_obj(std::string_view text, const std::string& name);
TriMesh read_off(std::string_view text, const std::string& name);
TriMesh read_ply(std::string_view data, const std::string& name);
TriMesh read_stl(std::string_view data, const std::string& name);

// Writers return the whole file's content; write_mesh has checked the indices and element ids.
// `binary`: binary little-endian PLY / binary STL, else ASCII.
std::string format_obj(const TriMesh& mesh);
std::string format_off(const TriMesh& mesh);
std::string format_ply(const TriMesh& mesh, bool binary);
std::string format_stl(const TriMesh& mesh, bool binary);
std::string format_glb(const TriMesh& mesh, const GlbTexture* texture = nullptr);  // write only

}  // namespace meshquilt::io
