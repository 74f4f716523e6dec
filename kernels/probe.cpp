#include "probe.h"

#include <algorithm>
#include <cstring>

#include "probe_layout.h"
#if MESHQUILT_HAS_VULKAN
#include "probe_spv.h"
#endif

namespace meshquilt {
namespace {

using namespace kernels::probe_layout;

// The C++ twin of probe.comp.
void probe_cpu(const engine::CpuDispatch& dispatch) {
  ProbeParams params;
  std::memcpy(&params, dispatch.push_constants.data(), sizeof(params));
  const auto* input = static_cast<const uint*>(dispatch.bindings[PROBE_BINDING_INPUT]);
  auto* output = static_cast<uint*>(dispatch.bindings[PROBE_BINDING_OUTPUT]);
  const uint end = std::min(dispatch.first + dispatch.count, params.invocation_count);
  for (uint id = dispatch.first; id < end; ++id) output[id] = id * params.multiplier + input[id % params.input_count];
}

}  // namespace

const engine::KernelSpec& probe_kernel() {
  static const engine::KernelSpec spec{"probe",
#if MESHQUILT_HAS_VULKAN
                                       std::span<const std::uint32_t>(kernels::spirv::probe),
#else
                                       {},
#endif
                                       PROBE_BINDING_COUNT, sizeof(ProbeParams), PROBE_WORKGROUP_SIZE, &probe_cpu};
  return spec;
}

}  // namespace meshquilt
