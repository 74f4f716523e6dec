//! The mesh I/O entry points of mesh_io.h: they pick the format by extension and dispatch to mesh/io/.

#include "mesh/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/atomic_write.h"
#include "mesh/io/formats.h"
#include "core/memory_budget.h"
#include "mesh/validation.h"

namespace meshquilt {
namespace {

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string read_whole_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw IoError(ErrorKind::file_unreadable, name + ": cannot open: is a directory");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(ErrorKind::file_unreadable, name + ": cannot open: " + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw IoError(ErrorKind::file_unreadable, name + ": cannot open: cannot determine its size");
  in.seekg(0, std::ios::beg);
  // The text and the mesh parsed from it live together for a moment; a mesh takes at most about
  // as many bytes as its binary file and far fewer than its text.
  check_memory_budget(2.0 * static_cast<double>(size), name + ": reading this " + format_bytes(static_cast<double>(size)) + " file");
  std::string data(static_cast<size_t>(size), '\0');
  if (size > 0 && !in.read(data.data(), size)) {
    throw IoError(ErrorKind::file_unreadable, name + ": cannot open: read failed: " + std::strerror(errno));
  }
  return data;
}

}  // namespace

// Our own parsers rather than OpenMesh's: see mesh_io.h (element ids, non-manifold faces, speed).
// OpenMesh stays the independent reference in the tests.
TriMesh read_mesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string ext = lower_extension(file);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    throw IoError(ErrorKind::unknown_format, name + ": unknown mesh format '" + ext + "' (expected .obj .ply .off .stl)");
  }
  const std::string data = read_whole_file(file);
  return parse_mesh(data, ext, name);
}

TriMesh parse_mesh(std::string_view data, const std::string& extension, const std::string& name) {
  std::string ext = extension;
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    throw IoError(ErrorKind::unknown_format, name + ": unknown mesh format '" + ext + "' (expected .obj .ply .off .stl)");
  }
  TriMesh mesh;
  if (ext == ".obj") {
    mesh = io::read_obj(data, name);
  } else if (ext == ".ply") {
    mesh = io::read_ply(data, name);
  } else if (ext == ".off") {
    mesh = io::read_off(data, name);
  } else {
    mesh = io::read_stl(data, name);
  }
  validate_mesh(mesh, name);
  return mesh;
}

void check_mesh_output(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl" && ext != ".glb") {
    throw IoError(ErrorKind::unknown_format,
                  file.string() + ": unknown mesh format '" + ext + "' (expected .ply .obj .off .stl .glb)");
  }
}

void write_mesh(const TriMesh& mesh, const std::filesystem::path& file, const WriteOptions& options) {
  const std::string name = file.string();
  check_mesh_output(file);
  const std::string ext = lower_extension(file);
  if (!mesh.elements.empty() && mesh.elements.size() != mesh.triangles.size()) {
    throw IoError(ErrorKind::write_failed, name + ": " + std::to_string(mesh.elements.size()) + " element ids for " +
                                              std::to_string(mesh.triangles.size()) + " faces");
  }
  const auto num_vertices = static_cast<uint64_t>(mesh.positions.size());
  for (const Tri& t : mesh.triangles) {
    for (int32_t i : t) {
      if (i < 0 || static_cast<uint64_t>(i) >= num_vertices) {
        throw IoError(ErrorKind::write_failed, name + ": face vertex index " + std::to_string(i) + " out of range");
      }
    }
  }

  std::string content;
  if (ext == ".ply") {
    content = io::format_ply(mesh, options.binary);
  } else if (ext == ".obj") {
    content = io::format_obj(mesh);
  } else if (ext == ".off") {
    content = io::format_off(mesh);
  } else if (ext == ".glb") {
    content = io::format_glb(mesh);
  } else {
    content = io::format_stl(mesh, options.binary);
  }

  write_file_atomic(file, content, options.cancel);
}

void write_textured_glb(const TriMesh& mesh, const GlbTexture& texture, const std::filesystem::path& file) {
  const std::string name = file.string();
  if (lower_extension(file) != ".glb")
    throw IoError(ErrorKind::unknown_format, name + ": a texture needs a .glb output");
  if (texture.face_uv.size() != mesh.triangles.size())
    throw IoError(ErrorKind::write_failed, name + ": " + std::to_string(texture.face_uv.size()) + " textured faces for " +
                                               std::to_string(mesh.triangles.size()));
  if (texture.png.size() < 8 || texture.png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
    throw IoError(ErrorKind::write_failed, name + ": the texture is not a PNG");
  for (const Tri& t : mesh.triangles)
    for (int32_t i : t)
      if (i < 0 || static_cast<size_t>(i) >= mesh.positions.size())
        throw IoError(ErrorKind::write_failed, name + ": face vertex index " + std::to_string(i) + " out of range");
  write_file_atomic(file, io::format_glb(mesh, &texture));
}

}  // namespace meshquilt
