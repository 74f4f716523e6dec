#pragma once
//! Progress of a batch: one line per finished job and a bar with jobs done, failed and an ETA
//! on a terminal, or JSON lines (`--progress json`) for logs and tools.

#include <chrono>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "batch_manifest.h"
#include "progress.h"

namespace meshquilt::cli {

class BatchProgress {
 public:
  //! `selected`: jobs of this shard. The bar is drawn on stderr only when it is a terminal.
  BatchProgress(ProgressMode mode, const Manifest& manifest, std::string shard, size_t selected);

  void started(const BatchJob& job);
  //! A job not run: `reason` is "done" (its record matches) or "running" (locked elsewhere).
  void skipped(const BatchJob& job, const std::string& reason);
  //! A job that ran: `summary` is synth's summary when it succeeded; `error` its error otherwise.
  void succeeded(const BatchJob& job, double seconds, const nlohmann::json& summary);
  void failed(const BatchJob& job, double seconds, const std::string& error);
  //! `running_fraction`: the summed progress (0..1 each) of the jobs running now.
  void tick(size_t running, double running_fraction);
  //! Prints the closing line (or JSON event); returns the number of failed jobs.
  size_t finish();

 private:
  void draw(bool force);
  void clear_bar();
  double eta_seconds() const;

  ProgressMode mode_;
  bool terminal_;
  const Manifest& manifest_;
  std::string shard_;
  size_t selected_;
  size_t done_ = 0, failed_ = 0, already_done_ = 0, locked_ = 0;
  size_t running_ = 0;
  double running_fraction_ = 0.0;
  bool bar_drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace meshquilt::cli
