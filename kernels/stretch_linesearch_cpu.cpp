#include "stretch_linesearch_cpu.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "stretch_linesearch_layout.h"

namespace meshquilt::kernels {
namespace {

using namespace stretch_linesearch_layout;
using glm::vec3;

// The shader's constants: finite, so sums and comparisons stay ordered.
constexpr float kInfeasible = 1e30f;
constexpr float kInvPhi = 0.618033988749895f;  // (sqrt(5) - 1) / 2

uint pcg_hash(uint v) {
  const uint state = v * 747796405u + 2891336453u;
  const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

struct Problem {
  const vec2* bottom_uv;
  const vec2* top_uv;
  const StretchTet* tets;
  const uint* vertex_tets;
  float texture_height;
};

vec3 texture_corner(const Problem& s, uint code, uint moving, vec2 p) {
  if (code == moving) return vec3(p, s.texture_height);
  const uint v = code >> 1u;
  return (code & 1u) != 0u ? vec3(s.top_uv[v], s.texture_height) : vec3(s.bottom_uv[v], 0.0f);
}

// w |S adj(T)|_F^2 / det(T)^2, in the shader's order of operations.
float tet_energy(const Problem& s, const StretchTet& tet, uint moving, vec2 p) {
  const vec3 q0 = texture_corner(s, tet.corners.x, moving, p);
  const vec3 e1 = texture_corner(s, tet.corners.y, moving, p) - q0;
  const vec3 e2 = texture_corner(s, tet.corners.z, moving, p) - q0;
  const vec3 e3 = texture_corner(s, tet.corners.w, moving, p) - q0;
  const vec3 r1 = glm::cross(e2, e3);
  const vec3 r2 = glm::cross(e3, e1);
  const vec3 r3 = glm::cross(e1, e2);
  const float det = glm::dot(e1, r1);
  if (!(det > 0.0f)) return kInfeasible;
  const vec3 s0(tet.s0), s1(tet.s1), s2(tet.s2);
  const vec3 m0 = s0 * r1.x + s1 * r2.x + s2 * r3.x;
  const vec3 m1 = s0 * r1.y + s1 * r2.y + s2 * r3.y;
  const vec3 m2 = s0 * r1.z + s1 * r2.z + s2 * r3.z;
  return tet.s0.w * ((glm::dot(m0, m0) + glm::dot(m1, m1) + glm::dot(m2, m2)) / (det * det));
}

float vertex_energy(const Problem& s, uint begin, uint end, uint moving, vec2 p) {
  float sum = 0.0f;
  for (uint k = begin; k < end; ++k) sum += tet_energy(s, s.tets[s.vertex_tets[k]], moving, p);
  return sum;
}

float reach2(vec3 q, uint code, uint moving, vec2 p0) {
  const vec2 r = vec2(q) - p0;
  return code == moving ? 0.0f : glm::dot(r, r);
}

// One invocation: the new top uv of the vertex, or nothing when it stays.
std::optional<vec2> search(const Problem& s, const StretchParams& params, uint a, uint begin, uint end) {
  const uint moving = 2u * a + 1u;
  const vec2 p0 = s.top_uv[a];
  const uint h =
      pcg_hash(a ^ pcg_hash(params.iteration ^ pcg_hash(params.seed_lo ^ pcg_hash(params.seed_hi))));
  const float angle = static_cast<float>(h) * (6.28318530718f / 4294967296.0f);
  const vec2 d(std::cos(angle), std::sin(angle));
  const vec3 d3(d, 0.0f);

  float e0 = 0.0f;
  float lo = -kInfeasible;
  float hi = kInfeasible;
  float far2 = 0.0f;
  for (uint k = begin; k < end; ++k) {
    const StretchTet& tet = s.tets[s.vertex_tets[k]];
    const vec3 q0 = texture_corner(s, tet.corners.x, moving, p0);
    const vec3 q1 = texture_corner(s, tet.corners.y, moving, p0);
    const vec3 q2 = texture_corner(s, tet.corners.z, moving, p0);
    const vec3 q3 = texture_corner(s, tet.corners.w, moving, p0);
    const vec3 e1 = q1 - q0;
    const vec3 e2 = q2 - q0;
    const vec3 e3 = q3 - q0;
    const vec3 r1 = glm::cross(e2, e3);
    const vec3 r2 = glm::cross(e3, e1);
    const vec3 r3 = glm::cross(e1, e2);
    const float det0 = glm::dot(e1, r1);
    if (!(det0 > 0.0f)) return std::nullopt;  // an inverted or flat tet: leave the vertex where it is
    // det is linear in the moving corner: its gradient there is r1, r2, r3 or -(r1 + r2 + r3).
    const vec3 gradient = tet.corners.x == moving   ? -(r1 + r2 + r3)
                          : tet.corners.y == moving ? r1
                          : tet.corners.z == moving ? r2
                                                    : r3;
    const float det1 = glm::dot(d3, gradient);
    const float slack = (1.0f - params.min_volume_ratio) * det0;
    if (det1 > 0.0f)
      lo = std::max(lo, -slack / det1);
    else if (det1 < 0.0f)
      hi = std::min(hi, slack / -det1);
    far2 = std::max(
        far2,
        std::max(std::max(reach2(q0, tet.corners.x, moving, p0), reach2(q1, tet.corners.y, moving, p0)),
                 std::max(reach2(q2, tet.corners.z, moving, p0), reach2(q3, tet.corners.w, moving, p0))));
    e0 += tet_energy(s, tet, moving, p0);
  }
  const float reach = std::sqrt(far2);
  float left = std::max(lo, -reach);
  float right = std::min(hi, reach);

  float inner_left = right - kInvPhi * (right - left);
  float inner_right = left + kInvPhi * (right - left);
  float f_left = vertex_energy(s, begin, end, moving, p0 + inner_left * d);
  float f_right = vertex_energy(s, begin, end, moving, p0 + inner_right * d);
  for (uint step = 0; step < params.golden_steps; ++step) {
    if (f_left < f_right) {
      right = inner_right;
      inner_right = inner_left;
      f_right = f_left;
      inner_left = right - kInvPhi * (right - left);
      f_left = vertex_energy(s, begin, end, moving, p0 + inner_left * d);
    } else {
      left = inner_left;
      inner_left = inner_right;
      f_left = f_right;
      inner_right = left + kInvPhi * (right - left);
      f_right = vertex_energy(s, begin, end, moving, p0 + inner_right * d);
    }
  }
  const float t = 0.5f * (left + right);
  const vec2 p = p0 + t * d;
  if (vertex_energy(s, begin, end, moving, p) < e0) return p;
  return std::nullopt;
}

}  // namespace

void stretch_linesearch_cpu(const engine::CpuDispatch& dispatch) {
  StretchParams params;
  std::memcpy(&params, dispatch.push_constants.data(), sizeof(params));
  auto* top_uv = static_cast<vec2*>(dispatch.bindings[STRETCH_LINESEARCH_BINDING_TOP_UV]);
  const auto* offsets =
      static_cast<const uint*>(dispatch.bindings[STRETCH_LINESEARCH_BINDING_VERTEX_TET_OFFSETS]);
  const auto* batch = static_cast<const uint*>(dispatch.bindings[STRETCH_LINESEARCH_BINDING_BATCH]);
  const Problem problem{static_cast<const vec2*>(dispatch.bindings[STRETCH_LINESEARCH_BINDING_BOTTOM_UV]),
                        top_uv,
                        static_cast<const StretchTet*>(dispatch.bindings[STRETCH_LINESEARCH_BINDING_TETS]),
                        static_cast<const uint*>(dispatch.bindings[STRETCH_LINESEARCH_BINDING_VERTEX_TETS]),
                        params.texture_height};
  const uint end = std::min(dispatch.first + dispatch.count, params.count);
  for (uint id = dispatch.first; id < end; ++id) {
    const uint a = batch[params.first + id];
    // Other invocations read only top corners of vertices outside this colour, never top_uv[a].
    if (const std::optional<vec2> moved = search(problem, params, a, offsets[a], offsets[a + 1]))
      top_uv[a] = *moved;
  }
}

}  // namespace meshquilt::kernels
