#include "atomic_file.h"

#include <unistd.h>

#include "core/error.h"
#include "core/atomic_write.h"

namespace meshquilt::cli {

void write_text_atomic(const std::filesystem::path& file, const std::string& text) { write_file_atomic(file, text); }

void check_writable(const std::filesystem::path& file) {
  std::filesystem::path folder = file.parent_path();
  if (folder.empty()) folder = ".";
  if (!std::filesystem::is_directory(folder))
    throw IoError(ErrorKind::write_failed, file.string() + ": folder " + folder.string() + " does not exist");
  if (access(folder.c_str(), W_OK) != 0)
    throw IoError(ErrorKind::write_failed, file.string() + ": folder " + folder.string() + " is not writable");
  if (std::filesystem::is_directory(file))
    throw IoError(ErrorKind::write_failed, file.string() + ": is a folder");
}

}  // namespace meshquilt::cli
