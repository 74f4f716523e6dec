#pragma once
//! Nearest-face grids kept in files between jobs. A grid depends only on its mesh, the build's
//! arguments and the builder, and geometry matching's answers never depend on the grid (it only
//! says how fast they come), so a job over a swatch met before reads the grid instead of building
//! it (docs/decisions/0020). A file is trusted only after every check a reader needs (offsets, indices, orderings
//! and a checksum of the whole): a damaged one is rebuilt and replaced, never read.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/tri_mesh.h"
#include "spatial/near_face_grid.h"

namespace meshquilt {

//! The arguments of build_near_face_grid other than the mesh.
struct NearFaceGridRequest {
  double voxel = 0.0;
  double margin = 0.0;
  double list_margin = 0.0;
  double far = 0.0;
  int max_list = 48;
  int64_t max_voxels = int64_t{1} << 18;
  std::vector<uint32_t> face_groups;

  NearFaceGrid build(const TriMesh& mesh) const;
};

//! Where a grid came from.
enum class GridSource {
  built,    //!< built, with no folder to keep it in
  read,     //!< read from the folder
  written,  //!< built and written to the folder
  unsaved,  //!< built; the folder could not take it
};

const char* to_string(GridSource source);

//! The grid of `mesh` for `request`: read from `folder` when a file there holds it, else built
//! and written there (as "<key>.grid", at most `kept_files` files in all, the least recently used
//! removed first). An empty folder builds every time. A folder that cannot be created or written
//! only costs the file: the grid is still returned.
NearFaceGrid cached_near_face_grid(const std::filesystem::path& folder, const TriMesh& mesh,
                                   const NearFaceGridRequest& request, GridSource* source = nullptr,
                                   int kept_files = 8);

//! The file form: 128 bits that name the mesh, request and builder, as hex (the file's name).
std::string near_face_grid_key(const TriMesh& mesh, const NearFaceGridRequest& request);
std::string near_face_grid_bytes(const NearFaceGrid& grid, std::string_view key);
//! The grid in `bytes` when they hold a whole, consistent grid for `key`, over `faces` faces
//! with `labels` face labels; nothing otherwise.
std::optional<NearFaceGrid> near_face_grid_from_bytes(std::string_view bytes, std::string_view key, size_t faces,
                                                      uint32_t labels);

}  // namespace meshquilt
