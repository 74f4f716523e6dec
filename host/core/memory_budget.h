#pragma once
//! The process-wide memory budget: how many bytes one job may plan to allocate. Readers check a
//! file's declared counts against it before allocating, and `synth` checks its output-size
//! estimate against it before starting.

#include <cstdint>
#include <string>

namespace meshquilt {

//! Bytes this process may use: the smallest of the physical memory, the cgroup's memory limit
//! (v2 `memory.max` or v1 `memory.limit_in_bytes`, as set by Slurm or a container) and
//! RLIMIT_AS / RLIMIT_DATA. Read once.
uint64_t memory_limit_bytes();

//! The default budget: three quarters of memory_limit_bytes(), leaving room for the libraries,
//! the allocator's slack and the rest of the machine.
uint64_t default_memory_budget();

//! Sets the budget (the CLI's --max-memory); 0 restores the default. Not thread-safe: call it
//! before work starts.
void set_memory_budget(uint64_t bytes);

//! The budget in force.
uint64_t memory_budget();

//! Parses "2G", "512M", "1.5GiB", "800k" or a plain byte count (powers of 1024).
//! \throw OptionError naming the parameter `option` when the text is not such a size or is 0.
uint64_t parse_memory_size(const std::string& text, const std::string& option = "max_memory");

//! "1.5 GiB", "12.0 MiB", "900 B".
std::string format_bytes(double bytes);

//! \throw InputError(too_large) "WHAT needs about X, more than the memory budget Y (raise it
//!        with --max-memory)" when `bytes` exceeds memory_budget().
void check_memory_budget(double bytes, const std::string& what);

}  // namespace meshquilt
