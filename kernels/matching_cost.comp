#version 450
// Geometry matching cost (Eq. 1-2 of the mesh quilting paper): for each (candidate translation,
// output point) pair, the minimum over swatch faces of D = (1 + lambda*Dist)(1 + |n_p - n_f|),
// found by a ring search over the swatch's x-y grid. The C++ twin is matching_cost_cpu.cpp;
// keep the two in step.
#extension GL_GOOGLE_include_directive : require
#include "matching_cost_layout.h"

layout(local_size_x = MATCHING_COST_WORKGROUP_SIZE) in;

layout(std430, set = 0, binding = MATCHING_COST_BINDING_FACES) readonly buffer Faces { MatchingFace faces[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_CELL_START) readonly buffer CellStart { uint cell_start[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_CELL_FACES) readonly buffer CellFaces { uint cell_faces[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_POINTS) readonly buffer Points { MatchingPoint points[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_TRANSLATIONS) readonly buffer Translations { vec2 translations[]; };
layout(std430, set = 0, binding = MATCHING_COST_BINDING_COSTS) writeonly buffer Costs { float costs[]; };
layout(push_constant, std430) uniform Push { MatchingCostParams params; };

const float kHuge = 3.0e38;

float segment_distance2(vec3 p, vec3 a, vec3 b) {
  vec3 ab = b - a;
  float t = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-30), 0.0, 1.0);
  vec3 d = p - (a + t * ab);
  return dot(d, d);
}

// Squared distance from p to triangle abc: Ericson, Real-Time Collision Detection, 5.1.5.
// Divisions are guarded so that near-degenerate input cannot produce NaN.
float triangle_distance2(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ab = b - a;
  vec3 ac = c - a;
  vec3 ap = p - a;
  float d1 = dot(ab, ap);
  float d2 = dot(ac, ap);
  vec3 closest;
  if (d1 <= 0.0 && d2 <= 0.0) {
    closest = a;
  } else {
    vec3 bp = p - b;
    float d3 = dot(ab, bp);
    float d4 = dot(ac, bp);
    float vc = d1 * d4 - d3 * d2;
    vec3 cp = p - c;
    float d5 = dot(ab, cp);
    float d6 = dot(ac, cp);
    float vb = d5 * d2 - d1 * d6;
    float va = d3 * d6 - d5 * d4;
    if (d3 >= 0.0 && d4 <= d3) {
      closest = b;
    } else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
      closest = a + clamp(d1 / max(d1 - d3, 1e-30), 0.0, 1.0) * ab;
    } else if (d6 >= 0.0 && d5 <= d6) {
      closest = c;
    } else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
      closest = a + clamp(d2 / max(d2 - d6, 1e-30), 0.0, 1.0) * ac;
    } else if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
      closest = b + clamp((d4 - d3) / max((d4 - d3) + (d5 - d6), 1e-30), 0.0, 1.0) * (c - b);
    } else {
      float denom = va + vb + vc;
      if (!(denom > 0.0)) {
        return min(segment_distance2(p, a, b), min(segment_distance2(p, a, c), segment_distance2(p, b, c)));
      }
      closest = a + ab * (vb / denom) + ac * (vc / denom);
    }
  }
  vec3 d = p - closest;
  return dot(d, d);
}

// Eq. 2 for one query point q (already moved by -t) with unit normal n.
float point_cost(vec3 q, vec3 n) {
  float cs = params.cell_size;
  float lambda = params.lambda;
  int nx = params.grid_nx;
  int ny = params.grid_ny;
  vec2 rel = (q.xy - params.grid_origin) / cs;
  // One cell outside the grid stands for anything farther: the ring bounds stay valid (only
  // weaker) and integer arithmetic cannot overflow.
  int cx = int(clamp(floor(rel.x), -1.0, float(nx)));
  int cy = int(clamp(floor(rel.y), -1.0, float(ny)));
  vec2 grid_max = params.grid_origin + vec2(float(nx), float(ny)) * cs;
  vec2 outside = max(max(params.grid_origin - q.xy, q.xy - grid_max), vec2(0.0));
  float box_distance = length(outside);

  int r_first = max(max(max(-cx, cx - (nx - 1)), max(-cy, cy - (ny - 1))), 0);
  int r_last = max(max(cx, nx - 1 - cx), max(cy, ny - 1 - cy));
  float best = kHuge;
  for (int r = r_first; r <= r_last; ++r) {
    // Every face not yet seen lies in rings >= r, at least (r-1) cells away in x or y.
    float bound = max(float(r - 1) * cs, box_distance);
    if (1.0 + lambda * bound >= best) break;
    int j_first = max(cy - r, 0);
    int j_last = min(cy + r, ny - 1);
    for (int j = j_first; j <= j_last; ++j) {
      bool full_row = (j == cy - r) || (j == cy + r);
      int i_first = full_row ? max(cx - r, 0) : cx - r;
      int i_last = full_row ? min(cx + r, nx - 1) : cx + r;
      int step = full_row ? 1 : max(2 * r, 1);
      for (int i = i_first; i <= i_last; i += step) {
        if (i < 0 || i >= nx) continue;
        uint cell = uint(j * nx + i);
        uint k_end = cell_start[cell + 1u];
        for (uint k = cell_start[cell]; k < k_end; ++k) {
          MatchingFace f = faces[cell_faces[k]];
          float normal_factor = 1.0 + length(n - f.normal.xyz);
          vec3 middle = (f.a.xyz + f.b.xyz + f.c.xyz) * (1.0 / 3.0);
          float sphere_gap = max(length(q - middle) - f.a.w, 0.0);
          if ((1.0 + lambda * sphere_gap) * normal_factor >= best) continue;
          float dist2 = f.normal.w != 0.0
              ? min(segment_distance2(q, f.a.xyz, f.b.xyz),
                    min(segment_distance2(q, f.a.xyz, f.c.xyz), segment_distance2(q, f.b.xyz, f.c.xyz)))
              : triangle_distance2(q, f.a.xyz, f.b.xyz, f.c.xyz);
          best = min(best, (1.0 + lambda * sqrt(dist2)) * normal_factor);
        }
      }
    }
  }
  return best;
}

void main() {
  uint id = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (id >= params.invocation_count) return;
  uint point_count = params.point_count;
  if (params.mapping == MATCHING_COST_PER_PAIR) {
    uint c = id / point_count;
    uint i = id - c * point_count;
    MatchingPoint p = points[i];
    costs[id] = point_cost(p.position.xyz - vec3(translations[c], 0.0), p.normal.xyz);
  } else {
    MatchingPoint p = points[id];
    for (uint c = 0u; c < params.candidate_count; ++c)
      costs[c * point_count + id] = point_cost(p.position.xyz - vec3(translations[c], 0.0), p.normal.xyz);
  }
}
