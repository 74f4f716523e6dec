#pragma once
//! The C++ twin of matching_cost.comp: the same ring search in float32, run by the CPU back end.

#include <glm/vec3.hpp>

#include "device.h"
#include "matching_cost_layout.h"

namespace meshquilt::kernels {

//! Runs invocations [dispatch.first, dispatch.first + dispatch.count) of the matching-cost
//! kernel over buffers laid out as matching_cost_layout.h says (Eq. 1-2 of the mesh quilting
//! paper). Called by the CPU back end; use MatchingCost rather than calling it directly.
//! The C++ twin runs without an iteration budget (MatchingCostParams::iteration_budget is
//! ignored): the CPU back end has no loop limiter.
void matching_cost_cpu(const engine::CpuDispatch& dispatch);

//! Eq. 2 for one query q (the point moved by -t) with unit normal n, on the host: the twin's
//! ring search over the swatch grid described by params (grid fields and lambda).
float matching_cost_cpu_point(const matching_cost_layout::MatchingFace* faces, const std::uint32_t* cell_start,
                              const std::uint32_t* cell_faces, const matching_cost_layout::MatchingCell* cells,
                              const matching_cost_layout::MatchingCostParams& params, glm::vec3 q, glm::vec3 n);

}  // namespace meshquilt::kernels
