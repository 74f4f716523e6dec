#pragma once
//! Runs the jobs of one shard of a manifest, each as a child `meshquilt synth|paint|relief` process.
//!
//! Why child processes rather than threads: the commands keep process-wide state (the interrupt token,
//! the memory budget of --max-memory, the list of pending temporary files), a job that runs out
//! of memory or crashes takes only itself down, and the output is byte-identical to a direct
//! run of the command by construction. Each child gets PR_SET_PDEATHSIG(SIGKILL), so a batch that is
//! killed (SIGKILL, a lost Slurm step) takes its jobs with it, and it inherits the job's flock,
//! so no rerun can start the same job while any writer of it is alive.

#include <cstddef>

#include "batch_manifest.h"
#include "batch_shard.h"
#include "progress.h"

namespace meshquilt::cli {

struct BatchOptions {
  Shard shard;                                     //!< which jobs to run
  int jobs = 1;                                    //!< jobs running at once
  int threads = 0;                                 //!< CPUs per job (0: this process's CPUs / jobs)
  ProgressMode progress = ProgressMode::automatic; //!< bar, JSON lines or nothing
};

struct BatchOutcome {
  size_t selected = 0;      //!< jobs in the shard
  size_t ran = 0;           //!< jobs started (or refused before starting)
  size_t failed = 0;        //!< jobs that failed (recorded in their failure records)
};

//! Runs every job of `options.shard` whose completion record does not match, `options.jobs` at
//! a time; records each success or failure. Each child is pinned to `threads` CPUs of this
//! process's set (sched_setaffinity; LP_NUM_THREADS for lavapipe), runs in the manifest's folder
//! and writes its stderr to the job's log. Output folders are created.
//! \throw Cancelled on SIGINT/SIGTERM (running jobs are stopped first and not recorded);
//!        IoError when the records folder cannot be written.
BatchOutcome run_batch(const Manifest& manifest, const BatchOptions& options);

}  // namespace meshquilt::cli
