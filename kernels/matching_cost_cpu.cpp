#include "matching_cost_cpu.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "matching_cost_layout.h"

namespace meshquilt::kernels {
namespace {

using namespace matching_cost_layout;
using glm::vec3;

constexpr uint kMaxGroups = 64;  // per voxel, on the stack; a voxel has at most one per normal bin

inline float segment_distance2(vec3 p, vec3 a, vec3 b) {
  const vec3 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-30f), 0.0f, 1.0f);
  const vec3 d = p - (a + t * ab);
  return glm::dot(d, d);
}

// The squared distance from p to triangle abc. The shader measures the plane when p projects
// inside and else every edge, selecting between them so that SIMD lanes never diverge; edges
// only for a degenerate triangle. Here a well-shaped triangle has the Voronoi region of p pick
// the one feature to measure (Ericson, Real-Time Collision Detection, 5.1.5), measured as the
// shader measures it. Other triangles keep the shader's way: rounding could put p in the wrong
// region of a thin one and measure a feature farther than the nearest, and a bound must never
// exceed the distance (the shader's inside test errs only toward the plane, which is nearer).
float triangle_distance2(vec3 p, vec3 a, vec3 b, vec3 c, bool degenerate, bool well_shaped) {
  const auto edges = [&] {
    return std::min(segment_distance2(p, a, b), std::min(segment_distance2(p, b, c), segment_distance2(p, c, a)));
  };
  if (degenerate) return edges();
  const vec3 ab = b - a, ac = c - a, ap = p - a;
  // n = ab x ac, computed only where a plane is measured or tested against.
  const auto plane = [&](vec3 n) {
    const float h = glm::dot(ap, n);
    return h * h / std::max(glm::dot(n, n), 1e-30f);  // as the shader divides
  };
  if (!well_shaped) {
    const vec3 n = glm::cross(ab, ac);
    if (glm::dot(n, n) > 0.0f && glm::dot(glm::cross(b - p, c - p), n) >= 0.0f &&
        glm::dot(glm::cross(c - p, a - p), n) >= 0.0f && glm::dot(glm::cross(a - p, b - p), n) >= 0.0f)
      return plane(n);
    return edges();
  }
  const auto to = [&](vec3 corner) { return glm::dot(p - corner, p - corner); };
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return to(a);
  const vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return to(b);
  if (d1 * d4 - d3 * d2 <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return segment_distance2(p, a, b);
  const vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return to(c);
  if (d5 * d2 - d1 * d6 <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return segment_distance2(p, c, a);
  if (d3 * d6 - d5 * d4 <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f) return segment_distance2(p, b, c);
  return plane(glm::cross(ab, ac));
}

struct Swatch {
  const MatchingFace* faces;
  const MatchingListed* voxel_faces;
  const MatchingVoxel* voxels;
  const MatchingGroup* groups;
  const MatchingCostParams& params;
};

// The minimum of best and D over the faces of group g that can beat best (`factor`: the
// point's bound on the normal term over the group's bin).
float scan_group(const Swatch& s, const MatchingGroup& g, float factor, vec3 q, vec3 n, float best) {
  const float lambda = s.params.box_low.w;
  for (uint k = g.first; k < g.end; ++k) {
    const MatchingListed& listed = s.voxel_faces[k];
    // Entries come nearest first: once one cannot beat the best, none after it can.
    if ((1.0f + lambda * listed.near) * factor >= best) break;
    const MatchingFace& f = s.faces[listed.face];
    const float normal_factor = 1.0f + glm::length(n - vec3(f.normal));
    const float sphere_gap = glm::length(q - vec3(f.sphere)) - f.sphere.w;
    // The distance to the face's plane is at most the distance to the face.
    const float plane_gap = f.normal.w == 0.0f ? std::abs(glm::dot(q - vec3(f.a), vec3(f.normal))) : 0.0f;
    // Nor can a face facing away or far off. One test of the larger of the three distance bounds
    // rejects what the shader's two tests reject: a branch per bound mispredicts more than the
    // sphere's distance it may spare.
    if ((1.0f + lambda * std::max(std::max(sphere_gap, plane_gap), listed.near)) * normal_factor >= best) continue;
    const float dist2 = triangle_distance2(q, vec3(f.a), vec3(f.b), vec3(f.c), f.normal.w != 0.0f, f.a.w != 0.0f);
    best = std::min(best, (1.0f + lambda * std::sqrt(dist2)) * normal_factor);
  }
  return best;
}

// The voxel holding q, or -1 outside the grid.
int voxel_index(const MatchingCostParams& params, vec3 q) {
  const glm::ivec3 cell(glm::floor((q - vec3(params.origin)) / params.origin.w));
  if (cell.x < 0 || cell.y < 0 || cell.z < 0 || cell.x >= params.grid_nx || cell.y >= params.grid_ny ||
      cell.z >= params.grid_nz)
    return -1;
  return (cell.z * params.grid_ny + cell.y) * params.grid_nx + cell.x;
}

// `voxel_id` is voxel_index(q).
float point_bound(const Swatch& s, int voxel_id, vec3 q, vec3 n, const float* factors) {
  const MatchingCostParams& params = s.params;
  const float lambda = params.box_low.w;
  if (voxel_id < 0) {
    const vec3 outside = glm::max(glm::max(vec3(params.box_low) - q, q - vec3(params.box_high)), vec3(0.0f));
    return 1.0f + lambda * glm::length(outside);
  }
  const MatchingVoxel& voxel = s.voxels[voxel_id];
  float best = 1.0f + lambda * voxel.reach;
  // The group most likely to hold the minimum first; then the others that can still beat it.
  // Each group's bound is computed once (a voxel has at most one group per normal bin).
  float bounds[kMaxGroups];
  const MatchingGroup* groups = s.groups + voxel.first;
  const uint count = std::min<uint>(voxel.count, kMaxGroups);
  uint lowest = 0;
  float lowest_bound = best;
  for (uint g = 0; g < count; ++g) {
    bounds[g] = (1.0f + lambda * groups[g].near) * factors[groups[g].bin];
    if (bounds[g] < best) __builtin_prefetch(&s.voxel_faces[groups[g].first]);
    if (bounds[g] < lowest_bound) {
      lowest_bound = bounds[g];
      lowest = g;
    }
  }
  if (lowest_bound < best) best = scan_group(s, groups[lowest], factors[groups[lowest].bin], q, n, best);
  for (uint g = 0; g < count; ++g)
    if (g != lowest && bounds[g] < best) best = scan_group(s, groups[g], factors[groups[g].bin], q, n, best);
  // More groups than bins cannot come from a grid, but a bound must not skip any.
  for (uint g = count; g < voxel.count; ++g)
    if ((1.0f + lambda * groups[g].near) * factors[groups[g].bin] < best)
      best = scan_group(s, groups[g], factors[groups[g].bin], q, n, best);
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
                      static_cast<const MatchingVoxel*>(dispatch.bindings[MATCHING_COST_BINDING_VOXELS]),
                      static_cast<const MatchingGroup*>(dispatch.bindings[MATCHING_COST_BINDING_GROUPS]), params};
  const auto* factors = static_cast<const float*>(dispatch.bindings[MATCHING_COST_BINDING_FACTORS]);
  const uint point_count = params.point_count;
  const uint first = dispatch.first;
  const uint end = std::min(dispatch.first + dispatch.count, params.invocation_count);
  if (first >= end) return;
  // Point by point across the chunk's candidates (neighbours on the candidate grid), whose
  // queries fall in neighbouring voxels: the caches serve them better than candidate by candidate.
  const uint first_candidate = first / point_count, last_candidate = (end - 1) / point_count;
  // A pair waits on memory: its voxel's header, group headers and lists lie in a grid larger
  // than the caches. So the walk looks ahead: the voxel of the pair kVoxelAhead on has its header
  // fetched, the pair kGroupsAhead on (whose header has come by then) its group headers, and
  // point_bound fetches the lists of the groups it may scan before scanning the first.
  constexpr uint kVoxelAhead = 8, kGroupsAhead = 4;
  struct Pair {
    uint id, point;
    int voxel;
    vec3 q;
  };
  thread_local std::vector<Pair> pairs;
  pairs.clear();
  for (uint i = 0; i < point_count; ++i)
    for (uint c = first_candidate; c <= last_candidate; ++c) {
      const uint id = c * point_count + i;
      if (id < first || id >= end) continue;
      const vec3 q = vec3(points[i].position) - vec3(translations[c], 0.0f);
      pairs.push_back({id, i, voxel_index(params, q), q});
    }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (k + kVoxelAhead < pairs.size() && pairs[k + kVoxelAhead].voxel >= 0)
      __builtin_prefetch(&swatch.voxels[pairs[k + kVoxelAhead].voxel]);
    if (k + kGroupsAhead < pairs.size() && pairs[k + kGroupsAhead].voxel >= 0) {
      const MatchingVoxel& v = swatch.voxels[pairs[k + kGroupsAhead].voxel];
      const char* line = reinterpret_cast<const char*>(swatch.groups + v.first);
      const char* last = reinterpret_cast<const char*>(swatch.groups + v.first + v.count);
      for (; line < last; line += 64) __builtin_prefetch(line);
    }
    const Pair& pair = pairs[k];
    costs[pair.id] = point_bound(swatch, pair.voxel, pair.q, vec3(points[pair.point].normal),
                                 factors + static_cast<std::size_t>(pair.point) * params.bin_count);
  }
}

}  // namespace meshquilt::kernels
