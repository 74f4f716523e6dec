#pragma once
//! The CLI side of the memory budget (host/mesh/memory_budget.h): the --max-memory option and
//! the up-front size estimate of a synth job.

#include <CLI/CLI.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt::cli {

//! Adds `--max-memory SIZE` (e.g. 8G) to `cmd`; it sets the process-wide budget when parsed.
void add_max_memory_option(CLI::App* cmd);

//! Bytes a planar synth job of `width` x `height` swatch extents is expected to need at its
//! peak: the output mesh grows as the swatch's faces times the plane's area in swatch extents.
//! Calibrated on the default job (73,036 faces, 32 MiB peak) and the 304,162-face fruit job
//! (71 MiB): about 170 B a face beyond a fixed part; budgeted at 400 B a face plus 64 MiB for
//! the formatted output, Embree and allocator slack.
double estimate_synth_bytes(const TriMesh& swatch, double width, double height);

//! \throw InputError(too_large) "--plane WxH: the output (about N faces) needs about X, more
//!        than the memory budget Y (raise it with --max-memory)".
void check_synth_memory(const TriMesh& swatch, double width, double height);

}  // namespace meshquilt::cli
