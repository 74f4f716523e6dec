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
layout(std430, set = 0, binding = MATCHING_COST_BINDING_CELL_BOUNDS) readonly buffer Cells { MatchingCell cells[]; };
layout(push_constant, std430) uniform Push { MatchingCostParams params; };

const float kHuge = 3.0e38;

float segment_distance2(vec3 p, vec3 a, vec3 b) {
  vec3 ab = b - a;
  float t = clamp(dot(p - a, ab) / max(dot(ab, ab), 1e-30), 0.0, 1.0);
  vec3 d = p - (a + t * ab);
  return dot(d, d);
}

// Squared distance from p to triangle abc, exact: to the plane when p projects inside the
// triangle, else to the nearest edge. Branch-free, so SIMD lanes never diverge in it; a
// degenerate triangle (no usable plane) uses its edges only.
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

// A lower bound of D over the faces of one cell: distance to their box, and the angle between n
// and the normal cone (|n - n_f| = 2 sin(angle / 2) >= 2 sin((phi - theta) / 2)).
float cell_bound(MatchingCell cell, vec3 q, vec3 n) {
  vec3 outside = max(max(cell.box_low.xyz - q, q - cell.box_high.xyz), vec3(0.0));
  float cos_theta = cell.box_low.w;
  float sin_theta = cell.box_high.w;
  float cos_phi = clamp(dot(n, cell.cone_axis.xyz), -1.0, 1.0);
  float normal_gap = 0.0;
  if (cos_phi < cos_theta) {
    float sin_phi = sqrt(max(1.0 - cos_phi * cos_phi, 0.0));
    float cos_psi = cos_phi * cos_theta + sin_phi * sin_theta;
    normal_gap = sqrt(max(2.0 - 2.0 * cos_psi, 0.0));
  }
  return (1.0 + params.lambda * length(outside)) * (1.0 + normal_gap);
}

// The ring search of one query: q = p - (t, 0) with the point's unit normal n.
struct Search {
  vec3 q;
  vec3 n;
  int cx, cy;          // q's cell, clamped to one cell outside the grid
  float box_distance;  // x-y distance from q to the grid's rectangle
  int r, r_last;       // current ring, last ring that touches the grid
  int i, j;            // next cell to open
  bool new_ring;       // ring r has not been tested against the bound yet
  uint k, k_end;       // faces of the open cell still to test
  float best;          // smallest D so far
};

int first_i(Search s, int j) {
  bool full_row = (j == s.cy - s.r) || (j == s.cy + s.r);
  return full_row ? max(s.cx - s.r, 0) : s.cx - s.r;
}

Search start_search(vec3 q, vec3 n) {
  Search s;
  s.q = q;
  s.n = n;
  int nx = params.grid_nx;
  int ny = params.grid_ny;
  vec2 rel = (q.xy - params.grid_origin) / params.cell_size;
  // One cell outside the grid stands for anything farther: the ring bounds stay valid (only
  // weaker) and integer arithmetic cannot overflow.
  s.cx = int(clamp(floor(rel.x), -1.0, float(nx)));
  s.cy = int(clamp(floor(rel.y), -1.0, float(ny)));
  vec2 grid_max = params.grid_origin + vec2(float(nx), float(ny)) * params.cell_size;
  s.box_distance = length(max(max(params.grid_origin - q.xy, q.xy - grid_max), vec2(0.0)));
  s.r = max(max(max(-s.cx, s.cx - (nx - 1)), max(-s.cy, s.cy - (ny - 1))), 0);
  s.r_last = max(max(s.cx, nx - 1 - s.cx), max(s.cy, ny - 1 - s.cy));
  s.j = max(s.cy - s.r, 0);
  s.i = first_i(s, s.j);
  s.new_ring = true;
  s.k = 0u;
  s.k_end = 0u;
  s.best = kHuge;
  return s;
}

// One step of the search: test one face, or open the next cell of the rings. Returns false when
// the search is over (s.best is then Eq. 2's minimum).
bool step(inout Search s) {
  if (s.k < s.k_end) {
    uint face = cell_faces[s.k];
    s.k += 1u;
    vec4 sphere = faces[face].sphere;
    vec4 normal = faces[face].normal;
    float normal_factor = 1.0 + length(s.n - normal.xyz);
    float sphere_gap = max(length(s.q - sphere.xyz) - sphere.w, 0.0);
    if ((1.0 + params.lambda * sphere_gap) * normal_factor < s.best) {
      float dist2 = triangle_distance2(s.q, faces[face].a.xyz, faces[face].b.xyz, faces[face].c.xyz, normal.w != 0.0);
      s.best = min(s.best, (1.0 + params.lambda * sqrt(dist2)) * normal_factor);
    }
    return true;
  }
  if (s.r > s.r_last) return false;
  if (s.new_ring) {
    // Every face not yet seen lies in rings >= r, at least (r-1) cells away in x or y, and
    // D >= 1 + lambda * Dist.
    float bound = max(float(s.r - 1) * params.cell_size, s.box_distance);
    if (1.0 + params.lambda * bound >= s.best) return false;
    s.new_ring = false;
  }
  int nx = params.grid_nx;
  int ny = params.grid_ny;
  if (s.i >= 0 && s.i < nx) {
    uint cell = uint(s.j * nx + s.i);
    uint k_first = cell_start[cell];
    uint k_end = cell_start[cell + 1u];
    if (k_first < k_end && cell_bound(cells[cell], s.q, s.n) < s.best) {
      s.k = k_first;
      s.k_end = k_end;
    }
  }
  // Ring r, row by row: whole rows at j = cy -+ r, only the two side cells in between.
  bool full_row = (s.j == s.cy - s.r) || (s.j == s.cy + s.r);
  if (full_row && s.i < min(s.cx + s.r, nx - 1)) {
    s.i += 1;
  } else if (!full_row && s.i == s.cx - s.r) {
    s.i = s.cx + s.r;
  } else {
    s.j += 1;
    if (s.j > min(s.cy + s.r, ny - 1)) {
      s.r += 1;
      s.j = max(s.cy - s.r, 0);
      s.new_ring = true;
    }
    s.i = first_i(s, s.j);
  }
  return true;
}

// llvmpipe ends every loop of an invocation once 65535 iterations have run in total, counted
// per SIMD vector. So the whole search is one flat loop whose lanes each count their steps
// (the vector then runs as many iterations as its busiest lane), and an invocation over budget
// stops and leaves its unfinished costs as the host set them, for the host to compute.
void main() {
  uint id = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (id >= params.invocation_count) return;
  uint point_count = params.point_count;
  uint c;
  uint c_end;
  uint i;
  if (params.mapping == MATCHING_COST_PER_PAIR) {
    c = id / point_count;
    c_end = c + 1u;
    i = id - c * point_count;
  } else {
    c = 0u;
    c_end = params.candidate_count;
    i = id;
  }
  MatchingPoint p = points[i];
  Search s = start_search(p.position.xyz - vec3(translations[c], 0.0), p.normal.xyz);
  uint budget = params.iteration_budget == 0u ? 0xFFFFFFFFu : params.iteration_budget;
  for (uint iteration = 0u; iteration < budget; ++iteration) {
    if (step(s)) continue;
    costs[c * point_count + i] = s.best;
    c += 1u;
    if (c >= c_end) break;
    s = start_search(p.position.xyz - vec3(translations[c], 0.0), p.normal.xyz);
  }
}
