#include "batch_runner.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "batch_progress.h"
#include "batch_records.h"
#include "cache_folder.h"
#include "core/error.h"
#include "exit_codes.h"
#include "signals.h"

extern char** environ;

namespace meshquilt::cli {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

struct RunningJob {
  const BatchJob* job = nullptr;
  JobLock lock;
  pid_t pid = -1;
  int output_fd = -1;   // the child's stdout: its command's JSON progress lines
  size_t slot = 0;      // which CPU subset it runs on
  std::string pending;  // a partial line read from output_fd
  double fraction = 0.0;
  json summary;
  Clock::time_point start;
};

std::string executable_path() {
  std::vector<char> path(4096);
  const ssize_t n = ::readlink("/proc/self/exe", path.data(), path.size() - 1);
  if (n <= 0) throw Error(ErrorKind::internal, std::string("/proc/self/exe: cannot read: ") + std::strerror(errno));
  return std::string(path.data(), static_cast<size_t>(n));
}

std::vector<int> allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> cpus;
  if (sched_getaffinity(0, sizeof set, &set) == 0)
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
      if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
  if (cpus.empty()) cpus.push_back(0);
  return cpus;
}

// Removes temporaries that a killed writer of `output` left (".NAME.PID.N.tmp"). Only called
// while holding the job's lock, when no writer of this output can be alive.
void remove_stale_temporaries(const std::filesystem::path& output) {
  std::string prefix = ".";
  prefix.append(output.filename().string()).append(".");
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(output.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > prefix.size() + 4 && name.compare(0, prefix.size(), prefix) == 0 &&
        name.compare(name.size() - 4, 4, ".tmp") == 0)
      std::filesystem::remove(entry.path(), error);
  }
}

// The error of a failed job: the last line its command wrote to stderr, without the "meshquilt: ".
std::string last_error_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  const std::string prefix = "meshquilt: ";
  if (last.compare(0, prefix.size(), prefix) == 0) last = last.substr(prefix.size());
  return last;
}

class Runner {
 public:
  Runner(const Manifest& manifest, const BatchOptions& options, BatchProgress& progress)
      : manifest_(manifest), options_(options), progress_(progress), executable_(executable_path()),
        cpus_(allowed_cpus()) {
    const int jobs = std::max(1, options.jobs);
    threads_ = options.threads > 0 ? options.threads : std::max<int>(1, static_cast<int>(cpus_.size()) / jobs);
    free_slots_.resize(static_cast<size_t>(jobs));
    for (size_t s = 0; s < free_slots_.size(); ++s) free_slots_[s] = free_slots_.size() - 1 - s;
    // The environment of every child: ours, with lavapipe's thread count set to the job's CPUs
    // and the grid cache named absolutely (a job runs in its own folder), so that all share it.
    for (char** variable = environ; *variable; ++variable)
      if (std::strncmp(*variable, "LP_NUM_THREADS=", 15) != 0 && std::strncmp(*variable, "MESHQUILT_CACHE=", 16) != 0)
        environment_.push_back(*variable);
    environment_.push_back("LP_NUM_THREADS=" + std::to_string(threads_));
    const std::filesystem::path grids = cache_folder();
    environment_.push_back("MESHQUILT_CACHE=" + (grids.empty() ? std::string("off") : std::filesystem::absolute(grids).string()));
  }

  // Starts `job` unless it is done or locked; returns whether it is now running.
  bool offer(const BatchJob& job) {
    const JobFiles files = job_files(manifest_, job);
    std::optional<JobLock> lock = JobLock::try_acquire(files.lock);
    if (!lock) {
      progress_.skipped(job, "running");
      return false;
    }
    if (completion_matches(manifest_, job)) {
      progress_.skipped(job, "done");
      return false;
    }
    ++outcome_.ran;
    progress_.started(job);
    if (!job.problem.empty()) {
      record_failure(manifest_, job, static_cast<int>(ErrorKind::file_unreadable), 0, job.problem, 0.0);
      progress_.failed(job, 0.0, job.problem);
      ++outcome_.failed;
      return false;
    }
    forget_completion(manifest_, job);
    for (const std::string& output : job.outputs) {
      const std::filesystem::path path = manifest_.resolve(output);
      std::error_code error;
      std::filesystem::create_directories(path.parent_path(), error);
      remove_stale_temporaries(path);
    }
    spawn(job, std::move(*lock));
    return true;
  }

  bool has_free_slot() const { return !free_slots_.empty(); }
  bool idle() const { return running_.empty(); }

  // Waits up to `timeout_ms` for output from the running jobs and finishes those that ended.
  void poll_running(int timeout_ms) {
    std::vector<pollfd> fds;
    for (const RunningJob& r : running_) fds.push_back({r.output_fd, POLLIN, 0});
    const int ready = ::poll(fds.data(), fds.size(), timeout_ms);
    if (ready < 0 && errno != EINTR) throw Error(ErrorKind::internal, std::string("poll: ") + std::strerror(errno));
    std::vector<size_t> ended;
    for (size_t i = 0; ready > 0 && i < fds.size(); ++i)
      if ((fds[i].revents & (POLLIN | POLLHUP | POLLERR)) && !read_output(running_[i])) ended.push_back(i);
    for (auto it = ended.rbegin(); it != ended.rend(); ++it) {
      finish(running_[*it]);
      running_.erase(running_.begin() + static_cast<std::ptrdiff_t>(*it));
    }
    double fraction = 0.0;
    for (const RunningJob& r : running_) fraction += r.fraction;
    progress_.tick(running_.size(), fraction);
  }

  // SIGINT/SIGTERM: stop the children (they remove their temporaries) and record nothing.
  void stop_all() {
    for (RunningJob& r : running_) ::kill(r.pid, SIGTERM);
    for (RunningJob& r : running_) {
      int status = 0;
      while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
      }
      ::close(r.output_fd);
    }
    running_.clear();
  }

  BatchOutcome outcome() const { return outcome_; }

 private:
  void spawn(const BatchJob& job, JobLock lock) {
    std::vector<std::string> arguments{executable_, job.command};
    for (const std::string& a : job.arguments()) arguments.push_back(a);
    arguments.push_back("--progress");
    arguments.push_back("json");
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<char*> envp;
    for (std::string& e : environment_) envp.push_back(e.data());
    envp.push_back(nullptr);

    const size_t slot = free_slots_.back();
    cpu_set_t cpus;
    CPU_ZERO(&cpus);
    for (int k = 0; k < threads_; ++k)
      CPU_SET(cpus_[(slot * static_cast<size_t>(threads_) + static_cast<size_t>(k)) % cpus_.size()], &cpus);

    const JobFiles files = job_files(manifest_, job);
    const int log_fd = ::open(files.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log_fd < 0) throw IoError(ErrorKind::write_failed, files.log.string() + ": cannot open: " + std::strerror(errno));
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
      ::close(log_fd);
      throw Error(ErrorKind::internal, std::string("pipe: ") + std::strerror(errno));
    }
    const std::string folder = manifest_.folder.string();
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) {
      // Only async-signal-safe calls between fork and exec.
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(127);  // the batch died before prctl took effect
      ::dup2(pipe_fds[1], STDOUT_FILENO);
      ::dup2(log_fd, STDERR_FILENO);
      [[maybe_unused]] const int kept_lock = ::dup(lock.fd());  // without O_CLOEXEC: the lock lives as long as the job
      ::sched_setaffinity(0, sizeof cpus, &cpus);
      if (::chdir(folder.c_str()) == 0) ::execve(argv[0], argv.data(), envp.data());
      static const char message[] = "meshquilt: cannot start meshquilt\n";
      [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message, sizeof message - 1);
      ::_exit(127);
    }
    ::close(pipe_fds[1]);
    ::close(log_fd);
    if (pid < 0) {
      ::close(pipe_fds[0]);
      throw Error(ErrorKind::internal, std::string("fork: ") + std::strerror(errno));
    }
    free_slots_.pop_back();
    RunningJob running{&job, std::move(lock), pid, pipe_fds[0], slot, {}, 0.0, json(), Clock::now()};
    running_.push_back(std::move(running));
  }

  // Reads what the child printed; false at end of file (the child is ending).
  bool read_output(RunningJob& r) {
    char buffer[4096];
    const ssize_t n = ::read(r.output_fd, buffer, sizeof buffer);
    if (n < 0) return errno == EINTR || errno == EAGAIN;
    if (n == 0) return false;
    r.pending.append(buffer, static_cast<size_t>(n));
    size_t newline;
    while ((newline = r.pending.find('\n')) != std::string::npos) {
      const std::string line = r.pending.substr(0, newline);
      r.pending.erase(0, newline + 1);
      const json event = json::parse(line, nullptr, /*allow_exceptions=*/false);
      if (!event.is_object()) continue;
      if (event.value("event", "") == "progress" && event.value("total", 0.0) > 0.0)
        r.fraction = std::clamp(event.value("done", 0.0) / event.value("total", 1.0), 0.0, 1.0);
      else if (event.value("event", "") == "done")
        r.summary = event.value("summary", json());
    }
    return true;
  }

  void finish(RunningJob& r) {
    ::close(r.output_fd);
    int status = 0;
    while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
    }
    free_slots_.push_back(r.slot);
    const double seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
    const BatchJob& job = *r.job;
    const JobFiles files = job_files(manifest_, job);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const int signal_number = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    if (code == 0 && r.summary.is_object()) {
      try {
        record_completion(manifest_, job, r.summary, seconds);
        progress_.succeeded(job, seconds, r.summary);
        return;
      } catch (const IoError& e) {
        record_failure(manifest_, job, exit_code(e.kind()), 0, message(e), seconds);
        progress_.failed(job, seconds, message(e));
        ++outcome_.failed;
        return;
      }
    }
    std::string error = last_error_line(files.log);
    if (signal_number != 0) error = "killed by signal " + std::to_string(signal_number) + (error.empty() ? "" : ": " + error);
    if (error.empty()) {
      error = job.command;
      error.append(" ended with exit code ").append(std::to_string(code));
    }
    record_failure(manifest_, job, code, signal_number, error, seconds);
    progress_.failed(job, seconds, error);
    ++outcome_.failed;
  }

  const Manifest& manifest_;
  const BatchOptions& options_;
  BatchProgress& progress_;
  std::string executable_;
  std::vector<int> cpus_;
  int threads_ = 1;
  std::vector<size_t> free_slots_;
  std::vector<std::string> environment_;
  std::vector<RunningJob> running_;
  BatchOutcome outcome_;
};

}  // namespace

BatchOutcome run_batch(const Manifest& manifest, const BatchOptions& options) {
  std::vector<const BatchJob*> selected;
  for (const BatchJob& job : manifest.jobs)
    if (options.shard.contains(job.index)) selected.push_back(&job);
  const std::filesystem::path records = records_folder(manifest);
  std::error_code error;
  std::filesystem::create_directories(records, error);
  if (error) throw IoError(ErrorKind::write_failed, records.string() + ": cannot create: " + error.message());

  BatchProgress progress(options.progress, manifest, options.shard.text(), selected.size());
  Runner runner(manifest, options, progress);
  size_t next = 0;
  while (next < selected.size() || !runner.idle()) {
    if (interrupt_token().cancelled()) {
      runner.stop_all();
      throw Cancelled();
    }
    while (runner.has_free_slot() && next < selected.size()) runner.offer(*selected[next++]);
    if (!runner.idle()) runner.poll_running(500);
  }
  progress.finish();
  BatchOutcome outcome = runner.outcome();
  outcome.selected = selected.size();
  return outcome;
}

}  // namespace meshquilt::cli
