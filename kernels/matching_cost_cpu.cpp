#include "matching_cost_cpu.h"

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

constexpr float kHuge = 3.0e38f;

float segment_distance2(vec3 p, vec3 a, vec3 b) {
  const vec3 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-30f), 0.0f, 1.0f);
  const vec3 d = p - (a + t * ab);
  return glm::dot(d, d);
}

// The shader's exact, branch-free distance: to the plane when p projects inside, else to the
// nearest edge; edges only for a degenerate triangle.
float triangle_distance2(vec3 p, vec3 a, vec3 b, vec3 c, bool degenerate) {
  const vec3 n = glm::cross(b - a, c - a);
  const float nn = glm::dot(n, n);
  const float u = glm::dot(glm::cross(b - p, c - p), n);
  const float v = glm::dot(glm::cross(c - p, a - p), n);
  const float w = glm::dot(glm::cross(a - p, b - p), n);
  const float h = glm::dot(p - a, n);
  const float plane2 = h * h / std::max(nn, 1e-30f);
  const float edge2 = std::min(segment_distance2(p, a, b), std::min(segment_distance2(p, b, c), segment_distance2(p, c, a)));
  const bool inside = !degenerate && nn > 0.0f && u >= 0.0f && v >= 0.0f && w >= 0.0f;
  return inside ? std::min(plane2, edge2) : edge2;
}

struct Swatch {
  const MatchingFace* faces;
  const uint* cell_start;
  const uint* cell_faces;
  const MatchingCell* cells;
  const MatchingCostParams& params;
};

// Lower bound of D over one cell's faces (see the shader's cell_bound).
float cell_bound(const MatchingCell& cell, float lambda, vec3 q, vec3 n) {
  const vec3 outside = glm::max(glm::max(vec3(cell.box_low) - q, q - vec3(cell.box_high)), vec3(0.0f));
  const float cos_theta = cell.box_low.w;
  const float sin_theta = cell.box_high.w;
  const float cos_phi = std::clamp(glm::dot(n, vec3(cell.cone_axis)), -1.0f, 1.0f);
  float normal_gap = 0.0f;
  if (cos_phi < cos_theta) {
    const float sin_phi = std::sqrt(std::max(1.0f - cos_phi * cos_phi, 0.0f));
    const float cos_psi = cos_phi * cos_theta + sin_phi * sin_theta;
    normal_gap = std::sqrt(std::max(2.0f - 2.0f * cos_psi, 0.0f));
  }
  return (1.0f + lambda * glm::length(outside)) * (1.0f + normal_gap);
}

// The shader runs this search as one flat loop of steps (see matching_cost.comp, because of
// llvmpipe's loop limiter); the order in which cells and faces are visited is the same.
float point_cost(const Swatch& s, vec3 q, vec3 n) {
  const MatchingCostParams& params = s.params;
  const float cs = params.cell_size;
  const float lambda = params.lambda;
  const int nx = params.grid_nx;
  const int ny = params.grid_ny;
  const glm::vec2 origin = params.grid_origin;
  const glm::vec2 q2(q.x, q.y);
  const glm::vec2 rel = (q2 - origin) / cs;
  // One cell outside the grid stands for anything farther (see the shader).
  const int cx = static_cast<int>(std::clamp(std::floor(rel.x), -1.0f, static_cast<float>(nx)));
  const int cy = static_cast<int>(std::clamp(std::floor(rel.y), -1.0f, static_cast<float>(ny)));
  const glm::vec2 grid_max = origin + glm::vec2(static_cast<float>(nx), static_cast<float>(ny)) * cs;
  const glm::vec2 outside = glm::max(glm::max(origin - q2, q2 - grid_max), glm::vec2(0.0f));
  const float box_distance = glm::length(outside);

  const int r_first = std::max({-cx, cx - (nx - 1), -cy, cy - (ny - 1), 0});
  const int r_last = std::max({cx, nx - 1 - cx, cy, ny - 1 - cy});
  float best = kHuge;
  for (int r = r_first; r <= r_last; ++r) {
    const float bound = std::max(static_cast<float>(r - 1) * cs, box_distance);
    if (1.0f + lambda * bound >= best) break;
    const int j_first = std::max(cy - r, 0);
    const int j_last = std::min(cy + r, ny - 1);
    for (int j = j_first; j <= j_last; ++j) {
      const bool full_row = j == cy - r || j == cy + r;
      const int i_first = full_row ? std::max(cx - r, 0) : cx - r;
      const int i_last = full_row ? std::min(cx + r, nx - 1) : cx + r;
      const int step = full_row ? 1 : std::max(2 * r, 1);
      for (int i = i_first; i <= i_last; i += step) {
        if (i < 0 || i >= nx) continue;
        const uint cell = static_cast<uint>(j * nx + i);
        const uint k_end = s.cell_start[cell + 1];
        if (s.cell_start[cell] == k_end || cell_bound(s.cells[cell], lambda, q, n) >= best) continue;
        for (uint k = s.cell_start[cell]; k < k_end; ++k) {
          const MatchingFace& f = s.faces[s.cell_faces[k]];
          const float normal_factor = 1.0f + glm::length(n - vec3(f.normal));
          const float sphere_gap = std::max(glm::length(q - vec3(f.sphere)) - f.sphere.w, 0.0f);
          if ((1.0f + lambda * sphere_gap) * normal_factor >= best) continue;
          const float dist2 = triangle_distance2(q, vec3(f.a), vec3(f.b), vec3(f.c), f.normal.w != 0.0f);
          best = std::min(best, (1.0f + lambda * std::sqrt(dist2)) * normal_factor);
        }
      }
    }
  }
  return best;
}

}  // namespace

float matching_cost_cpu_point(const MatchingFace* faces, const std::uint32_t* cell_start,
                              const std::uint32_t* cell_faces, const MatchingCell* cells,
                              const MatchingCostParams& params, glm::vec3 q, glm::vec3 n) {
  return point_cost(Swatch{faces, cell_start, cell_faces, cells, params}, q, n);
}

void matching_cost_cpu(const engine::CpuDispatch& dispatch) {
  MatchingCostParams params;
  std::memcpy(&params, dispatch.push_constants.data(), sizeof(params));
  const auto* points = static_cast<const MatchingPoint*>(dispatch.bindings[MATCHING_COST_BINDING_POINTS]);
  const auto* translations = static_cast<const vec2*>(dispatch.bindings[MATCHING_COST_BINDING_TRANSLATIONS]);
  auto* costs = static_cast<float*>(dispatch.bindings[MATCHING_COST_BINDING_COSTS]);
  const Swatch swatch{static_cast<const MatchingFace*>(dispatch.bindings[MATCHING_COST_BINDING_FACES]),
                      static_cast<const uint*>(dispatch.bindings[MATCHING_COST_BINDING_CELL_START]),
                      static_cast<const uint*>(dispatch.bindings[MATCHING_COST_BINDING_CELL_FACES]),
                      static_cast<const MatchingCell*>(dispatch.bindings[MATCHING_COST_BINDING_CELL_BOUNDS]), params};
  const uint point_count = params.point_count;
  const uint end = std::min(dispatch.first + dispatch.count, params.invocation_count);
  for (uint id = dispatch.first; id < end; ++id) {
    if (params.mapping == MATCHING_COST_PER_PAIR) {
      const uint c = id / point_count;
      const uint i = id - c * point_count;
      const MatchingPoint& p = points[i];
      costs[id] = point_cost(swatch, vec3(p.position) - vec3(translations[c], 0.0f), vec3(p.normal));
    } else {
      const MatchingPoint& p = points[id];
      for (uint c = 0; c < params.candidate_count; ++c)
        costs[c * point_count + id] =
            point_cost(swatch, vec3(p.position) - vec3(translations[c], 0.0f), vec3(p.normal));
    }
  }
}

}  // namespace meshquilt::kernels
