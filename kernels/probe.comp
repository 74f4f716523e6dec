#version 450
// A minimal kernel that exercises the engine: bindings, push constants, the linear invocation
// index over two-dimensional grids. Its C++ twin is probe_cpu.cpp.
#extension GL_GOOGLE_include_directive : require
#include "probe_layout.h"

layout(local_size_x = PROBE_WORKGROUP_SIZE) in;
layout(std430, set = 0, binding = PROBE_BINDING_INPUT) readonly buffer Input { uint input_values[]; };
layout(std430, set = 0, binding = PROBE_BINDING_OUTPUT) writeonly buffer Output { uint output_values[]; };
layout(push_constant, std430) uniform Push { ProbeParams params; };

void main() {
  uint id = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (id >= params.invocation_count) return;
  output_values[id] = id * params.multiplier + input_values[id % params.input_count];
}
