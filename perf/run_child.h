#pragma once
// Runs the CLI in a child process for the perf runners.

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace meshquilt::perf {

//! Runs argv (argv[0] a path) in a child with its stdout to `out`; returns the exit status (-1
//! when it did not exit normally) and, when `peak_kib` is given, its peak resident memory.
inline int run_child(const std::vector<std::string>& argv, const std::string& out = "/dev/null",
                     long* peak_kib = nullptr) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) dup2(fd, STDOUT_FILENO);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (peak_kib) *peak_kib = usage.ru_maxrss;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace meshquilt::perf
