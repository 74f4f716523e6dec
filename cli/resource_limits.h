#pragma once
//! The CLI side of the memory budget (host/core/memory_budget.h): the --max-memory option.

#include <CLI/CLI.hpp>

namespace meshquilt::cli {

//! Adds `--max-memory SIZE` (e.g. 8G) to `cmd`; it sets the process-wide budget when parsed.
void add_max_memory_option(CLI::App* cmd);

}  // namespace meshquilt::cli
