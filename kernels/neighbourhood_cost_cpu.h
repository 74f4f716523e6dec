#pragma once
//! The C++ twin of neighbourhood_cost.comp: the same sums, operation for operation in float32,
//! run by the CPU back end.

#include "device.h"

namespace meshquilt::kernels {

//! Runs invocations [dispatch.first, dispatch.first + dispatch.count) of the neighbourhood-cost
//! kernel over buffers laid out as neighbourhood_cost_layout.h says: each sums one candidate's
//! mismatch over its visit's neighbours. Called by the CPU back end; use NeighbourhoodCost
//! rather than calling it directly.
void neighbourhood_cost_cpu(const engine::CpuDispatch& dispatch);

}  // namespace meshquilt::kernels
