#pragma once
//! A minimal kernel for testing the engine: output[i] = i * multiplier + input[i % #input]
//! (uint32 arithmetic, wrapping). Layout in probe_layout.h.

#include "device.h"

namespace meshquilt {

//! The probe kernel's description for engine::Device::kernel.
const engine::KernelSpec& probe_kernel();

}  // namespace meshquilt
