#include "matching_cost_cpu.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "matching_cost_layout.h"

namespace meshquilt::kernels {
namespace {

using namespace matching_cost_layout;
using glm::vec3;

float segment_distance2(vec3 p, vec3 a, vec3 b) {
  const vec3 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-30f), 0.0f, 1.0f);
  const vec3 d = p - (a + t * ab);
  return glm::dot(d, d);
}

// The shader's distance: to the plane when p projects inside, else to the nearest edge; edges
// only for a degenerate triangle. The shader computes both and selects, so that SIMD lanes never
// diverge; here a branch skips the edges when the plane decides (inside, the plane is the
// nearest, up to rounding that the bound's margin covers).
float triangle_distance2(vec3 p, vec3 a, vec3 b, vec3 c, bool degenerate) {
  const vec3 n = glm::cross(b - a, c - a);
  const float nn = glm::dot(n, n);
  if (!degenerate && nn > 0.0f && glm::dot(glm::cross(b - p, c - p), n) >= 0.0f &&
      glm::dot(glm::cross(c - p, a - p), n) >= 0.0f && glm::dot(glm::cross(a - p, b - p), n) >= 0.0f) {
    const float h = glm::dot(p - a, n);
    return h * h / std::max(nn, 1e-30f);  // as the shader divides
  }
  return std::min(segment_distance2(p, a, b), std::min(segment_distance2(p, b, c), segment_distance2(p, c, a)));
}

struct Swatch {
  const MatchingFace* faces;
  const MatchingListed* voxel_faces;
  const MatchingVoxel* voxels;
  const MatchingCostParams& params;
};

float point_bound(const Swatch& s, vec3 q, vec3 n) {
  const MatchingCostParams& params = s.params;
  const float lambda = params.box_low.w;
  const glm::ivec3 cell(glm::floor((q - vec3(params.origin)) / params.origin.w));
  if (cell.x < 0 || cell.y < 0 || cell.z < 0 || cell.x >= params.grid_nx || cell.y >= params.grid_ny ||
      cell.z >= params.grid_nz) {
    const vec3 outside = glm::max(glm::max(vec3(params.box_low) - q, q - vec3(params.box_high)), vec3(0.0f));
    return 1.0f + lambda * glm::length(outside);
  }
  const MatchingVoxel& voxel = s.voxels[(cell.z * params.grid_ny + cell.y) * params.grid_nx + cell.x];
  float best = 1.0f + lambda * voxel.reach;
  for (uint k = voxel.first; k < voxel.first + voxel.count; ++k) {
    const MatchingListed& listed = s.voxel_faces[k];
    // Entries come nearest first: once one cannot beat the best, none after it can.
    if (1.0f + lambda * listed.near >= best) break;
    const MatchingFace& f = s.faces[listed.face];
    const float normal_factor = 1.0f + glm::length(n - vec3(f.normal));
    if ((1.0f + lambda * listed.near) * normal_factor >= best) continue;  // nor can this face, facing away
    const float sphere_gap = std::max(glm::length(q - vec3(f.sphere)) - f.sphere.w, 0.0f);
    if ((1.0f + lambda * sphere_gap) * normal_factor >= best) continue;
    const float dist2 = triangle_distance2(q, vec3(f.a), vec3(f.b), vec3(f.c), f.normal.w != 0.0f);
    best = std::min(best, (1.0f + lambda * std::sqrt(dist2)) * normal_factor);
  }
  return best;
}

}  // namespace

void matching_cost_cpu(const engine::CpuDispatch& dispatch) {
  MatchingCostParams params;
  std::memcpy(&params, dispatch.push_constants.data(), sizeof(params));
  const auto* points = static_cast<const MatchingPoint*>(dispatch.bindings[MATCHING_COST_BINDING_POINTS]);
  const auto* translations = static_cast<const vec2*>(dispatch.bindings[MATCHING_COST_BINDING_TRANSLATIONS]);
  auto* costs = static_cast<float*>(dispatch.bindings[MATCHING_COST_BINDING_COSTS]);
  const Swatch swatch{static_cast<const MatchingFace*>(dispatch.bindings[MATCHING_COST_BINDING_FACES]),
                      static_cast<const MatchingListed*>(dispatch.bindings[MATCHING_COST_BINDING_VOXEL_FACES]),
                      static_cast<const MatchingVoxel*>(dispatch.bindings[MATCHING_COST_BINDING_VOXELS]), params};
  const uint point_count = params.point_count;
  const uint end = std::min(dispatch.first + dispatch.count, params.invocation_count);
  for (uint id = dispatch.first; id < end; ++id) {
    const uint c = id / point_count;
    const uint i = id - c * point_count;
    const MatchingPoint& p = points[i];
    costs[id] = point_bound(swatch, vec3(p.position) - vec3(translations[c], 0.0f), vec3(p.normal));
  }
}

}  // namespace meshquilt::kernels
