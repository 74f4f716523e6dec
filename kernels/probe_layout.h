// Layout of the probe kernel (probe.comp and probe_cpu.cpp), valid GLSL and C++.
#ifndef MESHQUILT_PROBE_LAYOUT_H
#define MESHQUILT_PROBE_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace meshquilt::kernels::probe_layout {
using uint = std::uint32_t;
#endif

#define PROBE_WORKGROUP_SIZE 32
#define PROBE_BINDING_INPUT 0  // uint[input_count]
#define PROBE_BINDING_OUTPUT 1 // uint[invocation_count]
#define PROBE_BINDING_COUNT 2

// output[id] = id * multiplier + input[id % input_count]
struct ProbeParams {
  uint invocation_count;
  uint input_count;
  uint multiplier;
  uint padding;
};

#ifdef __cplusplus
static_assert(sizeof(ProbeParams) == 16 && offsetof(ProbeParams, multiplier) == 8);
}  // namespace meshquilt::kernels::probe_layout
#endif

#endif  // MESHQUILT_PROBE_LAYOUT_H
