#include "resource_limits.h"

#include <cstdio>
#include <string>

#include "core/memory_budget.h"

namespace meshquilt::cli {

void add_max_memory_option(CLI::App* cmd) {
  cmd->add_option_function<std::string>(
      "--max-memory", [](const std::string& text) { set_memory_budget(parse_memory_size(text)); },
      "memory budget for the job, e.g. 8G (default: " + format_bytes(static_cast<double>(default_memory_budget())) +
          ", 3/4 of the memory this process may use)");
}

}  // namespace meshquilt::cli
