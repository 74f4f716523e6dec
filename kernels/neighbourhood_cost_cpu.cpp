#include "neighbourhood_cost_cpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/vec3.hpp>

#include "neighbourhood_cost_layout.h"

namespace meshquilt::kernels {
namespace {

using namespace neighbourhood_cost_layout;

int wrapped(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

void neighbourhood_cost_cpu(const engine::CpuDispatch& dispatch) {
  NeighbourhoodCostParams params;
  std::memcpy(&params, dispatch.push_constants.data(), sizeof(params));
  const auto* sample = static_cast<const vec4*>(dispatch.bindings[NEIGHBOURHOOD_COST_BINDING_SAMPLE]);
  const auto* visits = static_cast<const NeighbourhoodVisit*>(dispatch.bindings[NEIGHBOURHOOD_COST_BINDING_VISITS]);
  const auto* neighbours =
      static_cast<const NeighbourhoodNeighbour*>(dispatch.bindings[NEIGHBOURHOOD_COST_BINDING_NEIGHBOURS]);
  const auto* candidates =
      static_cast<const NeighbourhoodCandidate*>(dispatch.bindings[NEIGHBOURHOOD_COST_BINDING_CANDIDATES]);
  auto* costs = static_cast<float*>(dispatch.bindings[NEIGHBOURHOOD_COST_BINDING_COSTS]);
  const int w = static_cast<int>(params.width), h = static_cast<int>(params.height);
  const auto texel = [&](int x, int y) {
    const vec4& s = sample[static_cast<uint>(y) * params.width + static_cast<uint>(x)];
    return glm::vec3(s.x, s.y, s.z);
  };
  const uint end = std::min(dispatch.first + dispatch.count, params.candidate_count);
  for (uint id = dispatch.first; id < end; ++id) {
    const NeighbourhoodCandidate& c = candidates[id];
    const NeighbourhoodVisit& visit = visits[c.visit];
    float cost = 0.0f;
    for (uint k = 0; k < visit.count; ++k) {
      const NeighbourhoodNeighbour& n = neighbours[visit.first + k];
      const vec2 p = c.fraction + vec2(n.offset.x, n.offset.y) - 0.5f;
      const vec2 f(std::floor(p.x), std::floor(p.y));
      const vec2 t = p - f;
      int x0 = c.pixel.x + static_cast<int>(f.x), y0 = c.pixel.y + static_cast<int>(f.y);
      if (x0 < 0 || x0 >= w) x0 = wrapped(x0, w);
      if (y0 < 0 || y0 >= h) y0 = wrapped(y0, h);
      const int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
      const glm::vec3 s = (1.0f - t.y) * ((1.0f - t.x) * texel(x0, y0) + t.x * texel(x1, y0)) +
                          t.y * ((1.0f - t.x) * texel(x0, y1) + t.x * texel(x1, y1));
      const glm::vec3 d = glm::vec3(n.colour.x, n.colour.y, n.colour.z) - s;
      cost += n.offset.z * (d.x * d.x + d.y * d.y + d.z * d.z);
    }
    costs[id] = cost;
  }
}

}  // namespace meshquilt::kernels
