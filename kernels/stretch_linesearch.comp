#version 450
// Random line searches on the L2 stretch of a shell map (Zhou et al. 2006, Sec. 3.2; Sander et
// al. 2001): each invocation moves the top texture corner of one atlas vertex along a hashed
// random direction to the golden-section minimum of
//   E(p) = sum over the vertex's tets of w * |S T(p)^-1|_F^2,
// keeping every tet's texture determinant above min_volume_ratio times its value before the move.
// The vertices of one dispatch share no tet (a colour of the host's graph colouring), so
// invocations are independent. The C++ twin is stretch_linesearch_cpu.cpp; keep the two in step.
#extension GL_GOOGLE_include_directive : require
#include "stretch_linesearch_layout.h"

layout(local_size_x = STRETCH_LINESEARCH_WORKGROUP_SIZE) in;

layout(std430, set = 0, binding = STRETCH_LINESEARCH_BINDING_BOTTOM_UV) readonly buffer BottomUv { vec2 bottom_uv[]; };
layout(std430, set = 0, binding = STRETCH_LINESEARCH_BINDING_TOP_UV) buffer TopUv { vec2 top_uv[]; };
layout(std430, set = 0, binding = STRETCH_LINESEARCH_BINDING_TETS) readonly buffer Tets { StretchTet tets[]; };
layout(std430, set = 0, binding = STRETCH_LINESEARCH_BINDING_VERTEX_TET_OFFSETS) readonly buffer Offsets { uint vertex_tet_offsets[]; };
layout(std430, set = 0, binding = STRETCH_LINESEARCH_BINDING_VERTEX_TETS) readonly buffer VertexTets { uint vertex_tets[]; };
layout(std430, set = 0, binding = STRETCH_LINESEARCH_BINDING_BATCH) readonly buffer Batch { uint batch[]; };
layout(push_constant, std430) uniform Push { StretchParams params; };

// A tet whose texture determinant is not positive costs this much: finite, so sums and
// comparisons stay ordered, and larger than any real stretch.
const float INFEASIBLE = 1e30;
const float INV_PHI = 0.618033988749895;  // (sqrt(5) - 1) / 2

uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Texture position of a corner; the moving corner (2a+1) sits at p.
vec3 texture_corner(uint code, uint moving, vec2 p) {
  if (code == moving) return vec3(p, params.texture_height);
  uint v = code >> 1u;
  return (code & 1u) != 0u ? vec3(top_uv[v], params.texture_height) : vec3(bottom_uv[v], 0.0);
}

// w |S T^-1|_F^2 = w |S adj(T)|_F^2 / det(T)^2; adj(T) has rows r1, r2, r3 (cross products of
// T's columns), so column j of S adj(T) is s0 r1[j] + s1 r2[j] + s2 r3[j].
float tet_energy(StretchTet tet, uint moving, vec2 p) {
  vec3 q0 = texture_corner(tet.corners.x, moving, p);
  vec3 e1 = texture_corner(tet.corners.y, moving, p) - q0;
  vec3 e2 = texture_corner(tet.corners.z, moving, p) - q0;
  vec3 e3 = texture_corner(tet.corners.w, moving, p) - q0;
  vec3 r1 = cross(e2, e3);
  vec3 r2 = cross(e3, e1);
  vec3 r3 = cross(e1, e2);
  float det = dot(e1, r1);
  if (!(det > 0.0)) return INFEASIBLE;
  vec3 m0 = tet.s0.xyz * r1.x + tet.s1.xyz * r2.x + tet.s2.xyz * r3.x;
  vec3 m1 = tet.s0.xyz * r1.y + tet.s1.xyz * r2.y + tet.s2.xyz * r3.y;
  vec3 m2 = tet.s0.xyz * r1.z + tet.s1.xyz * r2.z + tet.s2.xyz * r3.z;
  return tet.s0.w * ((dot(m0, m0) + dot(m1, m1) + dot(m2, m2)) / (det * det));
}

float vertex_energy(uint begin, uint end, uint moving, vec2 p) {
  float sum = 0.0;
  for (uint k = begin; k < end; ++k) sum += tet_energy(tets[vertex_tets[k]], moving, p);
  return sum;
}

float reach2(vec3 q, uint code, uint moving, vec2 p0) {
  vec2 r = q.xy - p0;
  return code == moving ? 0.0 : dot(r, r);
}

void main() {
  uint id = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (id >= params.count) return;
  uint a = batch[params.first + id];
  uint moving = 2u * a + 1u;
  uint begin = vertex_tet_offsets[a];
  uint end = vertex_tet_offsets[a + 1u];
  vec2 p0 = top_uv[a];

  uint h = pcg_hash(a ^ pcg_hash(params.iteration ^ pcg_hash(params.seed_lo ^ pcg_hash(params.seed_hi))));
  float angle = float(h) * (6.28318530718 / 4294967296.0);
  vec2 d = vec2(cos(angle), sin(angle));
  vec3 d3 = vec3(d, 0.0);

  // One pass over the tets: E(0), the interval where det(t) = det0 + t det1 stays above
  // ratio det0 (det1: d against the gradient of det in the moving corner), and the reach L.
  float e0 = 0.0;
  float lo = -INFEASIBLE;
  float hi = INFEASIBLE;
  float far2 = 0.0;
  for (uint k = begin; k < end; ++k) {
    StretchTet tet = tets[vertex_tets[k]];
    vec3 q0 = texture_corner(tet.corners.x, moving, p0);
    vec3 q1 = texture_corner(tet.corners.y, moving, p0);
    vec3 q2 = texture_corner(tet.corners.z, moving, p0);
    vec3 q3 = texture_corner(tet.corners.w, moving, p0);
    vec3 e1 = q1 - q0;
    vec3 e2 = q2 - q0;
    vec3 e3 = q3 - q0;
    vec3 r1 = cross(e2, e3);
    vec3 r2 = cross(e3, e1);
    vec3 r3 = cross(e1, e2);
    float det0 = dot(e1, r1);
    if (!(det0 > 0.0)) return;  // an inverted or flat tet: leave the vertex where it is
    vec3 gradient = tet.corners.x == moving ? -(r1 + r2 + r3)
                  : tet.corners.y == moving ? r1
                  : tet.corners.z == moving ? r2 : r3;
    float det1 = dot(d3, gradient);
    float slack = (1.0 - params.min_volume_ratio) * det0;
    if (det1 > 0.0) lo = max(lo, -slack / det1);
    else if (det1 < 0.0) hi = min(hi, slack / -det1);
    far2 = max(far2, max(max(reach2(q0, tet.corners.x, moving, p0), reach2(q1, tet.corners.y, moving, p0)),
                         max(reach2(q2, tet.corners.z, moving, p0), reach2(q3, tet.corners.w, moving, p0))));
    e0 += tet_energy(tet, moving, p0);
  }
  float reach = sqrt(far2);
  float left = max(lo, -reach);
  float right = min(hi, reach);

  // Golden-section search on [left, right]; t* is the middle of the final bracket.
  float inner_left = right - INV_PHI * (right - left);
  float inner_right = left + INV_PHI * (right - left);
  float f_left = vertex_energy(begin, end, moving, p0 + inner_left * d);
  float f_right = vertex_energy(begin, end, moving, p0 + inner_right * d);
  for (uint step = 0u; step < params.golden_steps; ++step) {
    if (f_left < f_right) {
      right = inner_right;
      inner_right = inner_left;
      f_right = f_left;
      inner_left = right - INV_PHI * (right - left);
      f_left = vertex_energy(begin, end, moving, p0 + inner_left * d);
    } else {
      left = inner_left;
      inner_left = inner_right;
      f_left = f_right;
      inner_right = left + INV_PHI * (right - left);
      f_right = vertex_energy(begin, end, moving, p0 + inner_right * d);
    }
  }
  float t = 0.5 * (left + right);
  vec2 p = p0 + t * d;
  if (vertex_energy(begin, end, moving, p) < e0) top_uv[a] = p;
}
