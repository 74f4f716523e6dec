#include "texture_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace meshquilt::cli {

bool is_texture_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".mqt";
}

}  // namespace meshquilt::cli
