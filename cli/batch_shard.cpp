#include "batch_shard.h"

#include <cstdlib>

#include "core/error.h"

namespace meshquilt::cli {
namespace {

bool parse_count(const std::string& text, long long* value) {
  if (text.empty()) return false;
  size_t used = 0;
  try {
    *value = std::stoll(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size();
}

long long slurm_variable(const char* name, long long fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  long long value = 0;
  if (!parse_count(text, &value))
    throw InputError(std::string(name) + ": expected a number, got '" + text + "'", ErrorKind::invalid_option);
  return value;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  long long index = -1, count = 0;
  if (slash == std::string::npos || !parse_count(text.substr(0, slash), &index) ||
      !parse_count(text.substr(slash + 1), &count) || count < 1 || index < 0 || index >= count)
    throw InputError("--shard: expected I/N with 0 <= I < N (e.g. 0/4), got '" + text + "'", ErrorKind::invalid_option);
  return Shard{static_cast<size_t>(index), static_cast<size_t>(count)};
}

Shard shard_from_environment() {
  const long long id = slurm_variable("SLURM_ARRAY_TASK_ID", -1);
  if (id < 0) return Shard{};
  const long long minimum = slurm_variable("SLURM_ARRAY_TASK_MIN", 0);
  const long long step = slurm_variable("SLURM_ARRAY_TASK_STEP", 1);
  const long long count = slurm_variable("SLURM_ARRAY_TASK_COUNT", 1);
  if (step < 1 || count < 1 || id < minimum || (id - minimum) % step != 0 || (id - minimum) / step >= count)
    throw InputError("SLURM_ARRAY_TASK_ID " + std::to_string(id) + " is not one of " + std::to_string(count) +
                         " tasks from " + std::to_string(minimum) + " by " + std::to_string(step) +
                         " (use a range such as --array=0-7 or 1-15:2, or pass --shard)",
                     ErrorKind::invalid_option);
  return Shard{static_cast<size_t>((id - minimum) / step), static_cast<size_t>(count)};
}

}  // namespace meshquilt::cli
