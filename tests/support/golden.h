#pragma once
// Fingerprints of output files for the golden tests: a change to any byte changes the hash.

#include <cstdint>
#include <cstdio>
#include <string>

namespace meshquilt::test {

// FNV-1a, 64 bits, as hex: independent of anything the code under test uses.
inline std::string fnv1a_hex(const std::string& bytes) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace meshquilt::test
