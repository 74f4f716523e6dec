#pragma once
//! Reading and writing triangle meshes: OBJ, PLY (ASCII and binary), OFF (incl. COFF), STL.
//!
//! The parsers are our own rather than OpenMesh's: OpenMesh drops the PLY face property
//! `element` and the OBJ groups that carry element ids, and reads large meshes several times
//! slower (perf/mesh_io_bench). They read the whole file at once and parse with std::from_chars.
//! Details: OBJ `v`/`f` (v, v/vt, v//vn, v/vt/vn, negative indices); PLY ascii and binary
//! little/big endian, any scalar types, unknown elements and properties skipped; OFF with
//! [ST][C][N]OFF headers, `#` comments, counts on the keyword line, per-vertex/face colours
//! ignored; STL ASCII and binary, exact duplicate vertices shared (near ones: weld_vertices).

#include <filesystem>
#include <string>
#include <string_view>

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Reads a mesh, choosing the format by extension (.obj .ply .off .stl, case-insensitive).
//! Polygons are fan-triangulated. Per-face element ids are read back from a PLY face property
//! `element`, or from OBJ groups when every face lies in a group named `element_N` (otherwise
//! `elements` stays empty); PLY vertex colours `red green blue` (or `r g b`; floats in [0, 1])
//! go to `colors`. The result has passed validate_mesh.
//! \throw IoError(file_unreadable) missing/unreadable; IoError(unknown_format) other extension;
//!        InputError(invalid_mesh) parse error, no faces, bad index, NaN/Inf coordinates, a
//!        header declaring more items than the file can hold; InputError(too_large) a file or
//!        declared mesh beyond the memory budget (memory_budget.h) or 2^31 vertices.
//!        Messages read "FILE: problem".
TriMesh read_mesh(const std::filesystem::path& file);

//! Parses mesh data already in memory; `extension` (".ply", ".OBJ", ...) picks the format and
//! `name` prefixes messages. Same result and errors as read_mesh (which calls it), without the
//! file access; the fuzz targets call it directly.
TriMesh parse_mesh(std::string_view data, const std::string& extension, const std::string& name);

class CancelToken;

struct WriteOptions {
  bool binary = true;                   //!< PLY/STL: binary (default) or ASCII
  const CancelToken* cancel = nullptr;  //!< polled while writing: Cancelled leaves `file` untouched
};

//! Writes a mesh, choosing the format by extension (.ply .obj .off .stl, or binary glTF .glb, write
//! only: io/write_glb.cpp). Element ids, when
//! present, go to a PLY face property `element` (int) or to OBJ groups `g element_N`; vertex
//! colours to PLY only (`red green blue`, uchar).
//! Atomic (write_file_atomic): a temporary file beside `file`, fsynced and renamed, so a failure
//! or a kill at any moment never leaves a truncated or overwritten output.
//! \throw IoError(unknown_format) other extension; IoError(write_failed) on any write error;
//!        Cancelled when options.cancel fires (no file changed).
//! Coordinates are written in shortest round-trip form (ASCII) or as doubles (PLY binary), so
//! PLY/OBJ/OFF round trips are exact; STL stores floats.
void write_mesh(const TriMesh& mesh, const std::filesystem::path& file, const WriteOptions& options = {});

//! An image mapped onto a mesh's faces, for binary glTF.
struct GlbTexture {
  std::vector<std::array<glm::vec2, 3>> face_uv;  //!< #F texture coordinates of each face's corners (glTF's: v down)
  std::string png;                                //!< the image, a whole PNG file
};

//! Writes `mesh` as binary glTF (.glb) with `texture` as its base colour (TEXCOORD_0, the PNG
//! embedded, a material that shows it), atomically as write_mesh writes.
//! \throw IoError(unknown_format) unless `file` ends in .glb; IoError(write_failed) for a
//!        texture whose face count or PNG does not fit, or any write error.
void write_textured_glb(const TriMesh& mesh, const GlbTexture& texture, const std::filesystem::path& file);

//! Whether write_mesh can write `file`'s format, checked before long work.
//! \throw IoError(unknown_format) naming the file.
void check_mesh_output(const std::filesystem::path& file);

}  // namespace meshquilt
