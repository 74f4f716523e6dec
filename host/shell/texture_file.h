#pragma once
//! A synthesized layer in texture space, on disk, so that `meshquilt embed` can place it over an
//! edited base without synthesizing again (Section 3.2 of the mesh quilting paper, last
//! paragraph).
//!
//! Format (binary, little-endian; version 2; version 1, without origins, is still read):
//!   "MQTEXTURE2\n"                                      11 bytes ("MQTEXTURE1\n" for version 1)
//!   u32 base_vertices, base_faces; u64 base_connectivity (FNV-1a of the base's triangles)
//!   f64 shell_height (0: the layer was embedded by normal displacement; no atlas follows)
//!   u32 charts, atlas_vertices, vertices, faces
//!   atlas: i32 face_chart[base_faces], i32 corners[3 base_faces], i32 vertex_base[A],
//!          i32 vertex_chart[A], f64 uv[2A], u8 on_boundary[A], f64 top_uv[2A]  (A = atlas_vertices;
//!          all absent when shell_height is 0)
//!   vertices: per vertex i32 base_face, f64 b1, f64 b2, f64 height
//!   faces: i32 triangles[3 faces], i32 elements[faces], i32 sources[faces]
//!   origins: i32 origin[vertices]  (version 2: the swatch vertex each vertex came from, -1 unknown)
//!   u64 FNV-1a of every byte before it
//! A vertex is the base point with barycentrics (1 - b1 - b2, b1, b2) in base_face, `height` above
//! it in base units.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "surface/surface_types.h"
#include "shell/shell_embedding.h"

namespace meshquilt {

struct QuiltTexture {
  uint32_t base_vertices = 0, base_faces = 0;
  uint64_t base_connectivity = 0;
  ShellTexture shell;  //!< empty atlas and height 0 for a normal-displacement layer
  std::vector<LocalVertex> vertices;
  std::vector<Tri> triangles;
  std::vector<int32_t> elements, sources;
  std::vector<int32_t> origins;  //!< #vertices swatch vertex per vertex (TriMesh::origins); empty from version 1
};

//! FNV-1a over the triangles' vertex indices: the connectivity a texture belongs to.
uint64_t connectivity_hash(const TriMesh& base);

//! The texture of a synthesized layer: `mesh` and `local` as quilt_surface returned them.
QuiltTexture make_quilt_texture(const TriMesh& base, const TriMesh& mesh,
                                const std::vector<LocalVertex>& local, const ShellTexture& shell);

//! The bytes of a texture file (the format above).
std::string format_texture(const QuiltTexture& texture);

//! Writes atomically. \throw IoError(write_failed).
void write_texture_file(const std::filesystem::path& file, const QuiltTexture& texture);

//! \throw IoError(file_unreadable) when it cannot be opened; InputError(bad_texture) "FILE: problem"
//! when it is truncated, corrupt or its indices are inconsistent.
QuiltTexture read_texture_file(const std::filesystem::path& file);

//! The bytes of a texture file; `name` is used in messages. Same errors as read_texture_file.
QuiltTexture parse_texture(const std::string& bytes, const std::string& name);

//! \throw InputError(base_mismatch) "BASE: problem" when `base` (prepared) is not the base the
//! texture was made over up to vertex positions: another vertex or face count, other triangles.
void check_texture_base(const QuiltTexture& texture, const TriMesh& base, const std::string& base_name);

}  // namespace meshquilt
