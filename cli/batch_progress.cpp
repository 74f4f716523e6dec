#include "batch_progress.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace meshquilt::cli {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

void print_json(const json& event) {
  std::printf("%s\n", event.dump().c_str());
  std::fflush(stdout);
}

}  // namespace

BatchProgress::BatchProgress(ProgressMode mode, const Manifest& manifest, std::string shard, size_t selected)
    : mode_(mode), terminal_(isatty(STDERR_FILENO) != 0), manifest_(manifest), shard_(std::move(shard)),
      selected_(selected), start_(Clock::now()), last_draw_(start_) {}

void BatchProgress::started(const BatchJob& job) {
  if (mode_ == ProgressMode::json)
    print_json({{"event", "job_start"}, {"job", job.index}, {"line", job.line}, {"output", job.output}});
}

void BatchProgress::skipped(const BatchJob& job, const std::string& reason) {
  (reason == "done" ? already_done_ : locked_) += 1;
  if (mode_ == ProgressMode::json) {
    print_json({{"event", "job_skip"}, {"job", job.index}, {"line", job.line}, {"output", job.output}, {"reason", reason}});
  } else if (reason != "done") {
    clear_bar();
    std::printf("%s %s: running in another process, skipped\n", manifest_.where(job).c_str(), job.output.c_str());
    std::fflush(stdout);
  }
}

void BatchProgress::succeeded(const BatchJob& job, double seconds, const json& summary) {
  ++done_;
  if (mode_ == ProgressMode::json) {
    print_json({{"event", "job_end"}, {"job", job.index}, {"line", job.line}, {"output", job.output},
                {"status", "done"}, {"seconds", seconds}, {"summary", summary}});
  } else {
    clear_bar();
    // Synth counts elements; paint and relief colour or raise vertices.
    const bool elements = summary.contains("elements");
    std::printf("%s %s: %lld faces, %lld %s in %.1f s\n", manifest_.where(job).c_str(), job.output.c_str(),
                summary.value("faces", 0LL), summary.value(elements ? "elements" : "vertices", 0LL),
                elements ? "elements" : "vertices", seconds);
    std::fflush(stdout);
  }
  draw(true);
}

void BatchProgress::failed(const BatchJob& job, double seconds, const std::string& error) {
  ++failed_;
  if (mode_ == ProgressMode::json) {
    print_json({{"event", "job_end"}, {"job", job.index}, {"line", job.line}, {"output", job.output},
                {"status", "failed"}, {"seconds", seconds}, {"error", error}});
  } else {
    clear_bar();
    std::fflush(stdout);
    std::fprintf(stderr, "meshquilt: %s: %s\n", manifest_.where(job).c_str(), error.c_str());
  }
  draw(true);
}

void BatchProgress::tick(size_t running, double running_fraction) {
  running_ = running;
  running_fraction_ = running_fraction;
  draw(false);
}

double BatchProgress::eta_seconds() const {
  const double to_run = static_cast<double>(selected_ - already_done_ - locked_);
  const double progressed = static_cast<double>(done_ + failed_) + running_fraction_;
  if (progressed <= 0.0) return -1.0;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  return std::max(0.0, elapsed * (to_run - progressed) / progressed);
}

void BatchProgress::draw(bool force) {
  const auto now = Clock::now();
  if (mode_ == ProgressMode::json) {
    // A JSON line at every job end and otherwise every 5 s: enough for a log, not a flood.
    if (!force && now - last_draw_ < std::chrono::seconds(5)) return;
    last_draw_ = now;
    print_json({{"event", "progress"}, {"done", done_}, {"failed", failed_}, {"already_done", already_done_},
                {"running", running_}, {"total", selected_},
                {"elapsed_s", std::chrono::duration<double>(now - start_).count()}, {"eta_s", eta_seconds()}});
    return;
  }
  if (mode_ != ProgressMode::automatic || !terminal_) return;
  if (!force && now - last_draw_ < std::chrono::milliseconds(250)) return;
  last_draw_ = now;
  const double eta = eta_seconds();
  char eta_text[32] = " ---";
  if (eta >= 0.0) std::snprintf(eta_text, sizeof eta_text, "%4.0f s", eta);
  std::fprintf(stderr, "\r\033[Kbatch %s: %zu/%zu done, %zu failed, %zu running  ETA %s", shard_.c_str(),
               done_ + already_done_, selected_, failed_, running_, eta_text);
  std::fflush(stderr);
  bar_drawn_ = true;
}

void BatchProgress::clear_bar() {
  if (!bar_drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  bar_drawn_ = false;
}

size_t BatchProgress::finish() {
  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  if (mode_ == ProgressMode::json) {
    print_json({{"event", "batch_end"}, {"shard", shard_}, {"jobs", selected_}, {"done", done_},
                {"already_done", already_done_}, {"failed", failed_}, {"running_elsewhere", locked_},
                {"seconds", seconds}});
  } else {
    clear_bar();
    std::printf("batch %s: %zu jobs: %zu done, %zu already done, %zu failed, %zu running elsewhere, in %.1f s\n",
                shard_.c_str(), selected_, done_, already_done_, failed_, locked_, seconds);
    std::fflush(stdout);
  }
  return failed_;
}

}  // namespace meshquilt::cli
