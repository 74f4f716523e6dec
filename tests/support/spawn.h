#pragma once
// Starts the built meshquilt executable as a child process the test can signal, and measures
// a finished child's peak memory.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

extern char** environ;

namespace meshquilt::test {

// Starts `meshquilt ARGS...` with stdout and stderr sent to `log` (or /dev/null); returns its pid.
inline pid_t spawn_cli(const std::vector<std::string>& args, const std::string& log = "/dev/null") {
  std::vector<std::string> all{MESHQUILT_CLI};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

struct ChildEnd {
  int exit_code = -1;   // when it exited
  int signal = 0;       // when a signal ended it
  long peak_rss_kib = 0;
};

inline ChildEnd wait_child(pid_t pid) {
  ChildEnd end;
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return end;
  if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
  end.peak_rss_kib = usage.ru_maxrss;
  return end;
}

}  // namespace meshquilt::test
