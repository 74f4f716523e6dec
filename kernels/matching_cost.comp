#version 450
// Geometry matching cost (Eq. 1-2 of the mesh quilting paper), bounded: for each (candidate
// translation, output point) pair, a lower bound of the minimum over swatch faces of
// D = (1 + lambda*Dist)(1 + |n_p - n_f|), from one voxel of the swatch's nearest-face grid:
// the minimum over the voxel's listed faces, capped by 1 + lambda*reach for every other face.
// Where the listed faces decide (a point near the swatch), the bound is the minimum itself.
// A voxel's faces come in groups of one normal bin; the point's factor for a bin bounds the
// normal term of all of them, so most groups are passed over whole.
// The C++ twin is matching_cost_cpu.cpp; keep the two in step.
#extension GL_GOOGLE_include_directive : require
#include "matching_cost_layout.h"

layout(local_size_x = MATCHING_COST_WORKGROUP_SIZE) in;

layout(std430, set = 0, binding = MATCHING_COST_BINDING_FACES) readonly buffer Faces { MatchingFace faces[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_VOXEL_FACES) readonly buffer VoxelFaces { MatchingListed voxel_faces[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_VOXELS) readonly buffer Voxels { MatchingVoxel voxels[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_POINTS) readonly buffer Points { MatchingPoint points[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_TRANSLATIONS) readonly buffer Translations { vec2 translations[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_COSTS) writeonly buffer Costs { float costs[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_GROUPS) readonly buffer Groups { MatchingGroup groups[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_FACTORS) readonly buffer Factors { float factors[]; };
layout(push_constant, std430) uniform Push { MatchingCostParams params; };

float segment_distance2(vec3 p, vec3 a, vec3 b) {
  vec3 ab = b - a;
  float t = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-30), 0.0, 1.0);
  vec3 d = p - (a + t * ab);
  return dot(d, d);
}

// Squared distance from p to triangle abc: to the plane when p projects inside the triangle,
// else to the nearest edge. Branch-free, so SIMD lanes never diverge in it; a degenerate
// triangle (no usable plane) uses its edges only.
float triangle_distance2(vec3 p, vec3 a, vec3 b, vec3 c, bool degenerate) {
  vec3 n = cross(b - a, c - a);
  float nn = dot(n, n);
  // Signed areas of the projection of p against each edge (all >= 0 inside).
  float u = dot(cross(b - p, c - p), n);
  float v = dot(cross(c - p, a - p), n);
  float w = dot(cross(a - p, b - p), n);
  float h = dot(p - a, n);
  float plane2 = h * h / max(nn, 1e-30);
  float edge2 = min(segment_distance2(p, a, b), min(segment_distance2(p, b, c), segment_distance2(p, c, a)));
  bool inside = !degenerate && nn > 0.0 && u >= 0.0 && v >= 0.0 && w >= 0.0;
  return inside ? min(plane2, edge2) : edge2;
}

// The minimum of best and D over the faces of group g that can beat best (`factor`: the
// point's bound on the normal term over the group's bin).
float scan_group(MatchingGroup g, float factor, vec3 q, vec3 n, float best) {
  float lambda = params.box_low.w;
  for (uint k = g.first; k < g.end; ++k) {
    MatchingListed listed = voxel_faces[k];
    // Entries come nearest first: once one cannot beat the best, none after it can.
    if ((1.0 + lambda * listed.near) * factor >= best) break;
    uint face = listed.face;
    vec4 normal = faces[face].normal;
    float normal_factor = 1.0 + length(n - normal.xyz);
    if ((1.0 + lambda * listed.near) * normal_factor >= best) continue;  // nor can this face, facing away
    vec4 sphere = faces[face].sphere;
    float sphere_gap = max(length(q - sphere.xyz) - sphere.w, 0.0);
    // The distance to the face's plane is at most the distance to the face.
    float plane_gap = normal.w == 0.0 ? abs(dot(q - faces[face].a.xyz, normal.xyz)) : 0.0;
    if ((1.0 + lambda * max(sphere_gap, plane_gap)) * normal_factor < best) {
      float dist2 = triangle_distance2(q, faces[face].a.xyz, faces[face].b.xyz, faces[face].c.xyz, normal.w != 0.0);
      best = min(best, (1.0 + lambda * sqrt(dist2)) * normal_factor);
    }
  }
  return best;
}

float point_bound(vec3 q, vec3 n, uint factor_base) {
  float lambda = params.box_low.w;
  ivec3 cell = ivec3(floor((q - params.origin.xyz) / params.origin.w));
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(params.grid_nx, params.grid_ny, params.grid_nz)))) {
    // Outside the grid: no face is nearer than the faces' box.
    vec3 outside = max(max(params.box_low.xyz - q, q - params.box_high.xyz), vec3(0.0));
    return 1.0 + lambda * length(outside);
  }
  MatchingVoxel voxel = voxels[(cell.z * params.grid_ny + cell.y) * params.grid_nx + cell.x];
  float best = 1.0 + lambda * voxel.reach;
  // The group most likely to hold the minimum first; then the others that can still beat it.
  uint lowest = voxel.first;
  float lowest_bound = best;
  for (uint g = voxel.first; g < voxel.first + voxel.count; ++g) {
    float bound = (1.0 + lambda * groups[g].near) * factors[factor_base + groups[g].bin];
    if (bound < lowest_bound) {
      lowest_bound = bound;
      lowest = g;
    }
  }
  if (lowest_bound < best) best = scan_group(groups[lowest], factors[factor_base + groups[lowest].bin], q, n, best);
  for (uint g = voxel.first; g < voxel.first + voxel.count; ++g) {
    MatchingGroup group = groups[g];
    float factor = factors[factor_base + group.bin];
    if (g != lowest && (1.0 + lambda * group.near) * factor < best) best = scan_group(group, factor, q, n, best);
  }
  return best;
}

void main() {
  uint id = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (id >= params.invocation_count) return;
  uint c = id / params.point_count;
  uint i = id - c * params.point_count;
  MatchingPoint p = points[i];
  costs[id] = point_bound(p.position.xyz - vec3(translations[c], 0.0), p.normal.xyz, i * params.bin_count);
}
