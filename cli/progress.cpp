#include "progress.h"

#include <unistd.h>

#include <cstdio>

#include "core/error.h"

namespace meshquilt::cli {

ProgressMode parse_progress_mode(const std::string& text) {
  if (text == "auto") return ProgressMode::automatic;
  if (text == "json") return ProgressMode::json;
  if (text == "none") return ProgressMode::none;
  throw InputError("--progress: expected auto, json or none, got '" + text + "'", ErrorKind::invalid_option);
}

ProgressReporter::ProgressReporter(ProgressMode mode, std::string task)
    : mode_(mode), terminal_(isatty(STDERR_FILENO) != 0), task_(std::move(task)),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressReporter::update(double done, double total) {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = total > 0.0 ? done / total : 1.0;
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
  if (mode_ == ProgressMode::json) {
    std::printf("{\"event\":\"progress\",\"task\":\"%s\",\"done\":%.6g,\"total\":%.6g,\"elapsed_s\":%.3f,\"eta_s\":%.3f}\n",
                task_.c_str(), done, total, elapsed, eta);
    std::fflush(stdout);
    return;
  }
  if (mode_ != ProgressMode::automatic || !terminal_) return;
  // Redraw at most ten times a second: a terminal is slow.
  if (done < total && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth + 0.5);
  std::string bar(static_cast<size_t>(filled), '#');
  bar.resize(kWidth, '.');
  if (eta >= 0.0)
    std::fprintf(stderr, "\r%s [%s] %3d%%  ETA %4.0f s ", task_.c_str(), bar.c_str(),
                 static_cast<int>(fraction * 100.0), eta);
  else
    std::fprintf(stderr, "\r%s [%s] %3d%%  ETA  --- ", task_.c_str(), bar.c_str(), static_cast<int>(fraction * 100.0));
  std::fflush(stderr);
}

void ProgressReporter::finish(const std::string& summary_json) {
  if (mode_ == ProgressMode::json) {
    std::printf("{\"event\":\"done\",\"task\":\"%s\",\"summary\":%s}\n", task_.c_str(), summary_json.c_str());
    std::fflush(stdout);
  } else if (mode_ == ProgressMode::automatic && terminal_) {
    std::fprintf(stderr, "\n");
  }
}

}  // namespace meshquilt::cli
