// The std430 layout shared by stretch_linesearch.comp and its C++ twin: buffer bindings, the tet
// struct and push constants. Valid GLSL (included with GL_GOOGLE_include_directive) and C++.
#ifndef MESHQUILT_STRETCH_LINESEARCH_LAYOUT_H
#define MESHQUILT_STRETCH_LINESEARCH_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace meshquilt::kernels::stretch_linesearch_layout {
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#endif

#define STRETCH_LINESEARCH_WORKGROUP_SIZE 64

// Storage-buffer bindings (set 0). #A atlas vertices, #T tets.
#define STRETCH_LINESEARCH_BINDING_BOTTOM_UV 0          // vec2[#A], read only
#define STRETCH_LINESEARCH_BINDING_TOP_UV 1             // vec2[#A], read-write
#define STRETCH_LINESEARCH_BINDING_TETS 2               // StretchTet[#T]
#define STRETCH_LINESEARCH_BINDING_VERTEX_TET_OFFSETS 3 // uint[#A + 1]
#define STRETCH_LINESEARCH_BINDING_VERTEX_TETS 4        // uint[offsets[#A]]: tets holding corner 2a+1
#define STRETCH_LINESEARCH_BINDING_BATCH 5              // uint[...]: atlas vertices, colours concatenated
#define STRETCH_LINESEARCH_BINDING_COUNT 6

// A tet of the shell map. Corner code c = 2 * atlas_vertex + layer; in texture space layer 0 sits
// at (bottom_uv[v], 0) and layer 1 at (top_uv[v], texture_height). The shell edge matrix
// S = [s0 s1 s2] (columns, shell corner k minus shell corner 0) is fixed.
struct StretchTet {
  uvec4 corners; // the four corner codes
  vec4 s0;       // xyz: first column of S; w: weight (> 0)
  vec4 s1;       // xyz: second column of S; w: unused (0)
  vec4 s2;       // xyz: third column of S; w: unused (0)
};

// Push constants of one dispatch: invocation i searches from atlas vertex batch[first + i].
struct StretchParams {
  uint first;             // start of this colour in the batch
  uint count;             // vertices of this colour (invocations)
  uint iteration;         // sweep number, hashed into the directions
  uint seed_lo;           // low and high words of the 64-bit seed
  uint seed_hi;
  uint golden_steps;      // golden-section iterations per line search
  float texture_height;   // H: the z of the top layer in texture space
  float min_volume_ratio; // a move keeps every tet's texture det >= ratio * its det before
};

#ifdef __cplusplus
static_assert(sizeof(StretchTet) == 64 && offsetof(StretchTet, s0) == 16 && offsetof(StretchTet, s2) == 48);
static_assert(sizeof(vec2) == 8, "std430 vec2 array stride");
static_assert(sizeof(StretchParams) == 32);
static_assert(offsetof(StretchParams, golden_steps) == 20 && offsetof(StretchParams, texture_height) == 24 &&
              offsetof(StretchParams, min_volume_ratio) == 28);
}  // namespace meshquilt::kernels::stretch_linesearch_layout
#endif

#endif  // MESHQUILT_STRETCH_LINESEARCH_LAYOUT_H
