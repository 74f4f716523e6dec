// The std430 layout shared by neighbourhood_cost.comp and its C++ twin: buffer bindings, element
// structs and push constants. Valid GLSL (included with GL_GOOGLE_include_directive) and C++.
#ifndef MESHQUILT_NEIGHBOURHOOD_COST_LAYOUT_H
#define MESHQUILT_NEIGHBOURHOOD_COST_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace meshquilt::kernels::neighbourhood_cost_layout {
using uint = std::uint32_t;
using ivec2 = glm::ivec2;
using vec2 = glm::vec2;
using vec4 = glm::vec4;
#endif

#define NEIGHBOURHOOD_COST_WORKGROUP_SIZE 64

// Storage-buffer bindings (set 0).
#define NEIGHBOURHOOD_COST_BINDING_SAMPLE 0     // vec4[width * height], row-major; xyz: the colour
#define NEIGHBOURHOOD_COST_BINDING_VISITS 1     // NeighbourhoodVisit[...]
#define NEIGHBOURHOOD_COST_BINDING_NEIGHBOURS 2 // NeighbourhoodNeighbour[...]
#define NEIGHBOURHOOD_COST_BINDING_CANDIDATES 3 // NeighbourhoodCandidate[candidate_count]
#define NEIGHBOURHOOD_COST_BINDING_COSTS 4      // float[candidate_count]
#define NEIGHBOURHOOD_COST_BINDING_COUNT 5

// A vertex being coloured: its neighbours are neighbours[first, first + count).
struct NeighbourhoodVisit {
  uint first;
  uint count;
  uint padding0;
  uint padding1;
};

// A coloured neighbour: where it lies in the visited vertex's frame, and its colour.
struct NeighbourhoodNeighbour {
  vec4 offset; // xy: offset in sample pixels; z: weight (>= 0); w: unused
  vec4 colour; // xyz: the neighbour's colour
};

// A sample position tried for a visit, as a whole pixel and a fraction in [0, 1): kept apart so
// that float32 reads neighbours beside it as exactly at any sample size.
struct NeighbourhoodCandidate {
  ivec2 pixel;   // in [0, width) x [0, height)
  vec2 fraction;
  uint visit;    // index into the visits
  uint padding;
};

// Push constants of one dispatch.
struct NeighbourhoodCostParams {
  uint width;           // the sample's size in pixels (>= 1)
  uint height;
  uint candidate_count; // invocations in this dispatch
  uint padding;
};

#ifdef __cplusplus
static_assert(sizeof(NeighbourhoodVisit) == 16);
static_assert(sizeof(NeighbourhoodNeighbour) == 32 && offsetof(NeighbourhoodNeighbour, colour) == 16);
static_assert(sizeof(NeighbourhoodCandidate) == 24 && offsetof(NeighbourhoodCandidate, visit) == 16);
static_assert(sizeof(NeighbourhoodCostParams) == 16);
}  // namespace meshquilt::kernels::neighbourhood_cost_layout
#endif

#endif  // MESHQUILT_NEIGHBOURHOOD_COST_LAYOUT_H
