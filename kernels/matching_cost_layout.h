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
#define MATCHING_COST_BINDING_VOXEL_FACES 1  // MatchingListed[...], the listed faces of every voxel
#define MATCHING_COST_BINDING_VOXELS 2       // MatchingVoxel[nx*ny*nz], x fastest
#define MATCHING_COST_BINDING_POINTS 3       // MatchingPoint[point_count]
#define MATCHING_COST_BINDING_TRANSLATIONS 4 // vec2[candidate_count]
#define MATCHING_COST_BINDING_COSTS 5        // float[candidate_count * point_count], candidate-major
#define MATCHING_COST_BINDING_GROUPS 6       // MatchingGroup[...], the groups of every voxel's list
#define MATCHING_COST_BINDING_FACTORS 7      // float[point_count * bin_count], point-major
#define MATCHING_COST_BINDING_COUNT 8

// A swatch face with what the bound needs precomputed on the host. The first two vectors are
// all a face needs to be rejected; the corners are read only for faces that pass.
struct MatchingFace {
  vec4 sphere; // xyz: centroid; w: radius of the bounding sphere around it (padded)
  vec4 normal; // xyz: the unit face normal Eq. 1 uses; w: 1 if the triangle is degenerate, else 0
  vec4 a;      // xyz: vertex 0; w: 1 if the triangle is well shaped (for the CPU twin), else 0
  vec4 b;      // xyz: vertex 1
  vec4 c;      // xyz: vertex 2
};

// A voxel of the swatch's nearest-face grid (host/spatial/near_face_grid.h).
struct MatchingVoxel {
  uint first;  // its groups: groups[first, first + count)
  uint count;
  float reach; // every face not listed is at least this far from the voxel (rounded down)
  float padding;
};

// A face listed for a voxel, and how near any point of the voxel can come to it; a voxel's
// entries come in increasing `near`.
struct MatchingListed {
  uint face;
  float near; // rounded down
};

// A group of a voxel's listed faces whose normals share a bin (host/spatial/normal_bins.h):
// for a point, every face of the group costs at least (1 + lambda * near) x the point's factor
// for the bin.
struct MatchingGroup {
  uint first;  // its faces: voxel_faces[first, end), in increasing near
  uint end;
  uint bin;
  float near;  // of its first face
};

// An output vertex: position and unit normal (w unused).
struct MatchingPoint {
  vec4 position;
  vec4 normal;
};

// Push constants of one dispatch.
struct MatchingCostParams {
  vec4 origin;           // xyz: the grid's lower corner; w: voxel edge
  vec4 box_low;          // xyz: the faces' bounding box; w: lambda (Eq. 1 weight)
  vec4 box_high;         // xyz: the faces' bounding box; w: unused
  int grid_nx;           // voxels along x, y, z (>= 1)
  int grid_ny;
  int grid_nz;
  uint point_count;      // points bound in this dispatch
  uint candidate_count;  // translations bound in this dispatch
  uint invocation_count; // pairs in this dispatch
  uint bin_count;        // normal bins: factors per point
  uint padding1;
};

#ifdef __cplusplus
static_assert(sizeof(MatchingFace) == 80 && offsetof(MatchingFace, normal) == 16 && offsetof(MatchingFace, c) == 64);
static_assert(sizeof(MatchingListed) == 8);
static_assert(sizeof(MatchingGroup) == 16 && offsetof(MatchingGroup, near) == 12);
static_assert(sizeof(MatchingVoxel) == 16 && offsetof(MatchingVoxel, reach) == 8);
static_assert(sizeof(MatchingPoint) == 32 && offsetof(MatchingPoint, normal) == 16);
static_assert(sizeof(vec2) == 8, "std430 vec2 array stride");
static_assert(sizeof(MatchingCostParams) == 80);
static_assert(offsetof(MatchingCostParams, box_low) == 16 && offsetof(MatchingCostParams, grid_nx) == 48 &&
              offsetof(MatchingCostParams, point_count) == 60 && offsetof(MatchingCostParams, invocation_count) == 68);
}  // namespace meshquilt::kernels::matching_cost_layout
#endif

#endif  // MESHQUILT_MATCHING_COST_LAYOUT_H
