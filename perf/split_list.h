#pragma once
// Splits option values such as "1,2,3" or a swatch's argument string for the perf runners.

#include <sstream>
#include <string>
#include <vector>

namespace meshquilt::perf {

//! The non-empty pieces of `text` between `sep` characters.
inline std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream s(text);
  for (std::string part; std::getline(s, part, sep);)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace meshquilt::perf
