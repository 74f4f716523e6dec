#pragma once
//! Wall-clock seconds per named stage, summed over a run (for the stats JSON).

#include <chrono>
#include <map>
#include <string>

namespace meshquilt {

//! Adds the seconds between its construction and destruction to `seconds[stage]`.
class StageTimer {
 public:
  StageTimer(std::map<std::string, double>& seconds, const char* stage)
      : seconds_(seconds), stage_(stage), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() {
    seconds_[stage_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  std::map<std::string, double>& seconds_;
  const char* stage_;
  std::chrono::steady_clock::time_point start_;
};

//! f(), with the seconds it took added to `seconds[stage]`: for a stage whose result is a const
//! (the value is returned as f returns it, so a type that cannot move works too).
template <typename F>
auto timed(std::map<std::string, double>& seconds, const char* stage, F&& f) {
  StageTimer timer(seconds, stage);
  return f();
}

}  // namespace meshquilt
