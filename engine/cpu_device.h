#pragma once
//! The CPU back end: buffers in host memory, kernels run as their C++ twins over TBB threads.

#include <memory>

#include "device.h"

namespace meshquilt::engine {

//! Opens the CPU back end (always succeeds). Invocations are split into chunks of whole
//! workgroups and run in parallel on TBB's default thread pool.
std::unique_ptr<Device> open_cpu_device();

}  // namespace meshquilt::engine
