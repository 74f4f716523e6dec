#pragma once
//! Progress reporting for long commands: a bar with an ETA on a terminal, or JSON lines.

#include <chrono>
#include <string>

namespace meshquilt::cli {

enum class ProgressMode { automatic, json, none };

//! Parses "auto", "json" or "none". \throw InputError(invalid_option) otherwise.
ProgressMode parse_progress_mode(const std::string& text);

class ProgressReporter {
 public:
  //! `automatic` draws a bar on stderr only when stderr is a terminal.
  ProgressReporter(ProgressMode mode, std::string task);
  //! Reports `done` of `total` units (cells, covered area); the ETA extrapolates linearly.
  void update(double done, double total);
  //! Ends the bar (newline) or writes a final JSON line with `summary` (a JSON object text).
  void finish(const std::string& summary_json);

 private:
  ProgressMode mode_;
  bool terminal_;
  std::string task_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace meshquilt::cli
