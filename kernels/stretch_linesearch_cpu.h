#pragma once
//! The C++ twin of stretch_linesearch.comp: the same random line searches in float32, run by the
//! CPU back end.

#include "device.h"

namespace meshquilt::kernels {

//! Runs invocations [dispatch.first, dispatch.first + dispatch.count) of the stretch line-search
//! kernel over buffers laid out as stretch_linesearch_layout.h says: each moves the top texture
//! corner of one atlas vertex of the batch along a hashed direction to lower its L2 stretch
//! (Sec. 3.2 of Zhou et al. 2006). Called by the CPU back end; use StretchLineSearch rather than
//! calling it directly.
void stretch_linesearch_cpu(const engine::CpuDispatch& dispatch);

}  // namespace meshquilt::kernels
