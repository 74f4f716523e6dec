#include "cache_folder.h"

#include <cstdlib>
#include <string_view>

namespace meshquilt::cli {

std::filesystem::path cache_folder() {
  if (const char* chosen = std::getenv("MESHQUILT_CACHE")) {
    const std::string_view folder(chosen);
    if (folder.empty() || folder == "off") return {};
    return std::filesystem::path(folder);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "meshquilt";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "meshquilt";
  return {};
}

}  // namespace meshquilt::cli
