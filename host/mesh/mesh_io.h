#pragma once
//! Reading and writing triangle meshes: OBJ, PLY (ASCII and binary), OFF (incl. COFF), STL.

#include <filesystem>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Reads a mesh, choosing the format by extension (.obj .ply .off .stl, case-insensitive).
//! Polygons are fan-triangulated. Per-face element ids are read back from a PLY face property
//! `element` or from OBJ groups, when present.
//! \throw IoError(file_unreadable) missing/unreadable; IoError(unknown_format) other extension;
//!        InputError(invalid_mesh) parse error, no faces, bad index, NaN/Inf coordinates.
//!        Messages read "FILE: problem".
TriMesh read_mesh(const std::filesystem::path& file);

struct WriteOptions {
  bool binary = true;  //!< PLY/STL: binary (default) or ASCII
};

//! Writes a mesh, choosing the format by extension (.ply .obj .off .stl). Element ids, when
//! present, go to a PLY face property `element` (int) or to OBJ groups `g element_N`.
//! Atomic: writes a temporary file beside `file` and renames it, so a failure never leaves a
//! truncated or overwritten output.
//! \throw IoError(unknown_format) other extension; IoError(write_failed) on any write error.
void write_mesh(const TriMesh& mesh, const std::filesystem::path& file, const WriteOptions& options = {});

}  // namespace meshquilt
