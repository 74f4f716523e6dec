#pragma once
//! The C++ twin of matching_cost.comp: the same bound in float32, run by the CPU back end.

#include "device.h"

namespace meshquilt::kernels {

//! Runs invocations [dispatch.first, dispatch.first + dispatch.count) of the matching-cost
//! kernel over buffers laid out as matching_cost_layout.h says (a lower bound of Eq. 2 of the
//! mesh quilting paper per pair). Called by the CPU back end; use MatchingCost rather than
//! calling it directly.
void matching_cost_cpu(const engine::CpuDispatch& dispatch);

}  // namespace meshquilt::kernels
