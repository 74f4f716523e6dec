#pragma once
//! Which jobs of a manifest one batch process runs: job i when i modulo `count` is `index`.

#include <cstddef>
#include <string>

namespace meshquilt::cli {

struct Shard {
  size_t index = 0;  //!< in [0, count)
  size_t count = 1;
  bool contains(size_t job_index) const { return job_index % count == index; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

//! Parses "I/N" with 0 <= I < N. \throw InputError(invalid_option) naming --shard.
Shard parse_shard(const std::string& text);

//! The shard of this Slurm array task: I = (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN) /
//! SLURM_ARRAY_TASK_STEP, N = SLURM_ARRAY_TASK_COUNT, so arrays that start above 0 or step by
//! more than 1 work (MIN defaults to 0, STEP to 1). Outside an array task: 0/1.
//! \throw InputError(invalid_option) when the variables do not describe a regular array.
Shard shard_from_environment();

}  // namespace meshquilt::cli
