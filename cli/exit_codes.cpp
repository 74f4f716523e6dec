#include "exit_codes.h"

#include <algorithm>

namespace meshquilt::cli {

int exit_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::internal: return static_cast<int>(ExitCode::internal);
    case ErrorKind::file_unreadable: return static_cast<int>(ExitCode::file_unreadable);
    case ErrorKind::unknown_format: return static_cast<int>(ExitCode::unknown_format);
    case ErrorKind::invalid_mesh: return static_cast<int>(ExitCode::invalid_mesh);
    case ErrorKind::invalid_option: return static_cast<int>(ExitCode::invalid_option);
    case ErrorKind::write_failed: return static_cast<int>(ExitCode::write_failed);
    case ErrorKind::device: return static_cast<int>(ExitCode::device);
    case ErrorKind::solver: return static_cast<int>(ExitCode::solver);
    case ErrorKind::interrupted: return static_cast<int>(ExitCode::interrupted);
    case ErrorKind::too_large: return static_cast<int>(ExitCode::too_large);
    case ErrorKind::bad_manifest: return static_cast<int>(ExitCode::bad_manifest);
    case ErrorKind::batch_incomplete: return static_cast<int>(ExitCode::batch_incomplete);
    case ErrorKind::bad_texture: return static_cast<int>(ExitCode::bad_texture);
    case ErrorKind::base_mismatch: return static_cast<int>(ExitCode::base_mismatch);
    case ErrorKind::swatch_unfit: return static_cast<int>(ExitCode::swatch_unfit);
  }
  return static_cast<int>(ExitCode::internal);
}

std::string with_options(const std::string& text) {
  return Error::render(text, [](std::string name) {
    std::replace(name.begin(), name.end(), '_', '-');
    return "--" + name;
  });
}

}  // namespace meshquilt::cli
