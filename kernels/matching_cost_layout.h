// The std430 layout shared by matching_cost.comp and its C++ twin: buffer bindings, element
// structs and push constants. Valid GLSL (included with GL_GOOGLE_include_directive) and C++.
#ifndef MESHQUILT_MATCHING_COST_LAYOUT_H
#define MESHQUILT_MATCHING_COST_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace meshquilt::kernels::matching_cost_layout {
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec4 = glm::vec4;
#endif

#define MATCHING_COST_WORKGROUP_SIZE 64

// Storage-buffer bindings (set 0).
#define MATCHING_COST_BINDING_FACES 0        // MatchingFace[#F]
#define MATCHING_COST_BINDING_CELL_START 1   // uint[nx*ny + 1], CSR offsets into cell faces
#define MATCHING_COST_BINDING_CELL_FACES 2   // uint[...], face indices per grid cell
#define MATCHING_COST_BINDING_POINTS 3       // MatchingPoint[point_count]
#define MATCHING_COST_BINDING_TRANSLATIONS 4 // vec2[candidate_count]
#define MATCHING_COST_BINDING_COSTS 5        // float[candidate_count * point_count], candidate-major
#define MATCHING_COST_BINDING_CELL_BOUNDS 6  // MatchingCell[nx*ny]
#define MATCHING_COST_BINDING_COUNT 7

// How invocations map to work (MatchingCostParams::mapping).
#define MATCHING_COST_PER_PAIR 0u  // one invocation per (candidate, point) pair
#define MATCHING_COST_PER_POINT 1u // one invocation per point, looping over candidates

// A swatch face with what the search needs precomputed on the host. The first two vectors
// are all a face needs to be rejected; the corners are read only for faces that pass.
struct MatchingFace {
  vec4 sphere; // xyz: centroid; w: radius of the bounding sphere around it (padded)
  vec4 normal; // xyz: unit face normal (zero if degenerate); w: 1 if degenerate, else 0
  vec4 a;      // xyz: vertex 0
  vec4 b;      // xyz: vertex 1
  vec4 c;      // xyz: vertex 2
};

// What bounds D over the faces of one grid cell: their 3D bounding box and a cone holding their
// normals (half-angle pi when a face has no normal), so a whole cell can be skipped.
struct MatchingCell {
  vec4 box_low;   // xyz: minimum corner of the faces' bounding box; w: cos(cone half-angle)
  vec4 box_high;  // xyz: maximum corner; w: sin(cone half-angle)
  vec4 cone_axis; // xyz: unit axis of the normal cone; w: 0
};

// An output vertex: position and unit normal (w unused).
struct MatchingPoint {
  vec4 position;
  vec4 normal;
};

// Push constants of one dispatch.
struct MatchingCostParams {
  vec2 grid_origin;      // x-y of the grid's lower corner
  float cell_size;       // grid cell edge (x and y)
  float lambda;          // Eq. 1 weight
  int grid_nx;           // cells along x (>= 1)
  int grid_ny;           // cells along y (>= 1)
  uint point_count;      // points bound in this dispatch
  uint candidate_count;  // translations bound in this dispatch
  uint invocation_count; // pairs (per pair) or points (per point)
  uint mapping;          // MATCHING_COST_PER_PAIR or MATCHING_COST_PER_POINT
  uint iteration_budget; // loop iterations an invocation may run (0: unlimited); pairs left
                         // unfinished keep the value the host put in their cost (negative)
  uint padding1;
};

#ifdef __cplusplus
static_assert(sizeof(MatchingFace) == 80 && offsetof(MatchingFace, normal) == 16 && offsetof(MatchingFace, c) == 64);
static_assert(sizeof(MatchingCell) == 48 && offsetof(MatchingCell, cone_axis) == 32);
static_assert(sizeof(MatchingPoint) == 32 && offsetof(MatchingPoint, normal) == 16);
static_assert(sizeof(vec2) == 8, "std430 vec2 array stride");
static_assert(sizeof(MatchingCostParams) == 48);
static_assert(offsetof(MatchingCostParams, cell_size) == 8 && offsetof(MatchingCostParams, grid_nx) == 16 &&
              offsetof(MatchingCostParams, point_count) == 24 && offsetof(MatchingCostParams, mapping) == 36 &&
              offsetof(MatchingCostParams, iteration_budget) == 40);
}  // namespace meshquilt::kernels::matching_cost_layout
#endif

#endif  // MESHQUILT_MATCHING_COST_LAYOUT_H
