#version 450
// The mismatch of an image neighbourhood against the sample at candidate positions, one
// invocation per candidate: sum over the visit's neighbours of weight x |colour - sample|^2, the
// sample read bilinearly between pixel centres and wrapped round its borders. Its C++ twin is in
// neighbourhood_cost_cpu.cpp.
#extension GL_GOOGLE_include_directive : require
#include "neighbourhood_cost_layout.h"

layout(local_size_x = NEIGHBOURHOOD_COST_WORKGROUP_SIZE) in;
layout(std430, set = 0, binding = NEIGHBOURHOOD_COST_BINDING_SAMPLE) readonly buffer Sample { vec4 sample_rgb[]; };
layout(std430, set = 0, binding = NEIGHBOURHOOD_COST_BINDING_VISITS) readonly buffer Visits { NeighbourhoodVisit visits[]; };
layout(std430, set = 0, binding = NEIGHBOURHOOD_COST_BINDING_NEIGHBOURS) readonly buffer Neighbours {
  NeighbourhoodNeighbour neighbours[];
};
layout(std430, set = 0, binding = NEIGHBOURHOOD_COST_BINDING_CANDIDATES) readonly buffer Candidates {
  NeighbourhoodCandidate candidates[];
};
layout(std430, set = 0, binding = NEIGHBOURHOOD_COST_BINDING_COSTS) writeonly buffer Costs { float costs[]; };
layout(push_constant, std430) uniform Push { NeighbourhoodCostParams params; };

int wrapped(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

vec3 texel(int x, int y) { return sample_rgb[uint(y) * params.width + uint(x)].xyz; }

void main() {
  uint id = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (id >= params.candidate_count) return;
  NeighbourhoodCandidate c = candidates[id];
  NeighbourhoodVisit visit = visits[c.visit];
  int w = int(params.width), h = int(params.height);
  float cost = 0.0;
  for (uint k = 0; k < visit.count; ++k) {
    NeighbourhoodNeighbour n = neighbours[visit.first + k];
    vec2 p = c.fraction + n.offset.xy - 0.5;
    vec2 f = floor(p);
    vec2 t = p - f;
    int x0 = c.pixel.x + int(f.x), y0 = c.pixel.y + int(f.y);
    if (x0 < 0 || x0 >= w) x0 = wrapped(x0, w);
    if (y0 < 0 || y0 >= h) y0 = wrapped(y0, h);
    int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
    vec3 s = (1.0 - t.y) * ((1.0 - t.x) * texel(x0, y0) + t.x * texel(x1, y0)) +
             t.y * ((1.0 - t.x) * texel(x0, y1) + t.x * texel(x1, y1));
    vec3 d = n.colour.xyz - s;
    cost += n.offset.z * dot(d, d);
  }
  costs[id] = cost;
}
