#pragma once
// Runs the built meshquilt executable for end-to-end tests.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace meshquilt::test {

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs `meshquilt ARGS` through the shell with stderr merged into stdout.
inline CliResult run_cli(const std::string& args) {
  const std::string command = std::string("'") + MESHQUILT_CLI + "' " + args + " 2>&1";
  CliResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// A fresh empty folder under the system temp folder, named for the test.
inline std::filesystem::path scratch_dir(const std::string& name) {
  // One per process: CTest runs each test of a suite as its own process, in parallel, and a
  // shared folder let one process clear or rewrite files another was reading.
  const auto dir =
      std::filesystem::temp_directory_path() / ("meshquilt_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace meshquilt::test
