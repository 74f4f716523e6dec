#pragma once
// One body per fuzz target, shared by the libFuzzer executables (tests/fuzz/*_fuzzer.cpp) and
// the corpus replay test of the normal build (tests/fuzz_corpus_test.cpp). A body feeds the
// bytes to a reader; the reader's own typed errors are expected, anything else (a crash, a
// sanitizer report, another exception type) is a finding.

#include <cstddef>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "mesh/base_mesh.h"
#include "core/memory_budget.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "surface/conformal_patch.h"
#include "surface/guidance_field.h"
#include "shell/texture_file.h"
#include "swatch/netpbm.h"

namespace meshquilt::fuzz {

// libFuzzer's default RSS limit is 2 GiB; a reader must refuse what would not fit in 256 MiB.
inline void limit_memory() { set_memory_budget(uint64_t{256} << 20); }

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

inline void mesh_body(const uint8_t* data, size_t size, const char* extension) {
  try {
    const TriMesh mesh = parse_mesh(as_text(data, size), extension, "fuzz");
    validate_mesh(mesh, "fuzz");  // parse_mesh promises a valid mesh: this must not throw
  } catch (const InputError&) {
  } catch (const IoError&) {
  }
}

inline void obj_body(const uint8_t* data, size_t size) { mesh_body(data, size, ".obj"); }
inline void ply_body(const uint8_t* data, size_t size) { mesh_body(data, size, ".ply"); }
inline void off_body(const uint8_t* data, size_t size) { mesh_body(data, size, ".off"); }
inline void stl_body(const uint8_t* data, size_t size) { mesh_body(data, size, ".stl"); }

// The swatch loader: the first byte picks the format, the rest is the file; then validation
// and the swatch frame (orientation, proportion checks) as `synth --swatch` runs them.
inline void swatch_body(const uint8_t* data, size_t size) {
  if (size == 0) return;
  static const char* extensions[] = {".obj", ".ply", ".off", ".stl"};
  try {
    const TriMesh mesh = parse_mesh(as_text(data + 1, size - 1), extensions[data[0] % 4], "fuzz");
    const TriMesh oriented = orient_swatch(mesh, "fuzz");
    validate_mesh(oriented, "fuzz");
  } catch (const InputError&) {
  } catch (const IoError&) {
  }
}

// The base loader: the first byte picks the format, the rest is the file; then the repairs and
// refusals of prepare_base as `synth --base` runs them. What it returns must be a valid mesh
// with every edge shared by at most two faces.
inline void base_body(const uint8_t* data, size_t size) {
  if (size == 0) return;
  static const char* extensions[] = {".obj", ".ply", ".off", ".stl"};
  try {
    const TriMesh mesh = parse_mesh(as_text(data + 1, size - 1), extensions[data[0] % 4], "fuzz");
    const TriMesh base = prepare_base(mesh, "fuzz");
    validate_mesh(base, "fuzz");
    if (inspect_surface(base).nonmanifold_edges != 0 || inspect_surface(base).misoriented_edges != 0) __builtin_trap();
  } catch (const InputError&) {
  } catch (const IoError&) {
  }
}

inline void netpbm_body(const uint8_t* data, size_t size) {
  try {
    const GrayImage image = parse_netpbm(std::string(as_text(data, size)), "fuzz");
    double sum = 0.0;
    for (double v : image.values) sum += v;  // touch every pixel: all must be initialised
    if (!(image.values.size() == static_cast<size_t>(image.width) * image.height) || !(sum >= 0.0)) __builtin_trap();
  } catch (const IoError&) {
  }
}

// The guidance-field reader against a fixed closed tetrahedron, then the interpolation the
// constraints feed (as `synth --field` runs them): every constraint must name a base vertex and
// every interpolated direction must be a finite unit vector.
inline const TriMesh& field_base() {
  static const TriMesh base{
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.3}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, {}, {}, {}};
  return base;
}

inline void field_body(const uint8_t* data, size_t size) {
  const TriMesh& base = field_base();
  static const BaseSurface surface(base);
  try {
    const std::vector<FieldConstraint> constraints = parse_field(as_text(data, size), "fuzz", base);
    for (const FieldConstraint& c : constraints)
      if (c.vertex < 0 || c.vertex >= static_cast<int32_t>(base.num_vertices())) __builtin_trap();
    const GuidanceField field = interpolate_field(surface, constraints);
    for (const Vec3& d : field.directions)
      if (!(std::abs(d.x * d.x + d.y * d.y + d.z * d.z - 1.0) < 1e-9)) __builtin_trap();
  } catch (const Error&) {
  }
}

// The texture-space reader of `meshquilt embed`: what it accepts must be safe to place, every
// index within the counts it states.
inline void texture_body(const uint8_t* data, size_t size) {
  try {
    const QuiltTexture t = parse_texture(std::string(as_text(data, size)), "fuzz");
    const size_t atlas_vertices = t.shell.atlas.uv.size();
    if (t.shell.top_uv.size() != atlas_vertices) __builtin_trap();
    for (const auto& corners : t.shell.atlas.corners)
      for (int32_t a : corners)
        if (a < 0 || static_cast<size_t>(a) >= atlas_vertices) __builtin_trap();
    for (const LocalVertex& v : t.vertices)
      if (v.point.face < 0 || static_cast<uint32_t>(v.point.face) >= t.base_faces) __builtin_trap();
    for (const Tri& tri : t.triangles)
      for (int32_t v : tri)
        if (v < 0 || static_cast<size_t>(v) >= t.vertices.size()) __builtin_trap();
    if (t.elements.size() != t.triangles.size() || t.sources.size() != t.triangles.size()) __builtin_trap();
  } catch (const InputError&) {
  }
}

}  // namespace meshquilt::fuzz
