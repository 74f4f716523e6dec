#include "atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <system_error>

#include "error.h"

namespace meshquilt::cli {

void write_text_atomic(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temp = file.string() + ".tmp" + std::to_string(getpid());
  {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw IoError(ExitCode::write_failed, file.string() + ": cannot write");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    throw IoError(ExitCode::write_failed, file.string() + ": cannot write: " + ec.message());
  }
}

void check_writable(const std::filesystem::path& file) {
  std::filesystem::path folder = file.parent_path();
  if (folder.empty()) folder = ".";
  if (!std::filesystem::is_directory(folder))
    throw IoError(ExitCode::write_failed, file.string() + ": folder " + folder.string() + " does not exist");
  if (access(folder.c_str(), W_OK) != 0)
    throw IoError(ExitCode::write_failed, file.string() + ": folder " + folder.string() + " is not writable");
  if (std::filesystem::is_directory(file))
    throw IoError(ExitCode::write_failed, file.string() + ": is a folder");
}

}  // namespace meshquilt::cli
