#pragma once
//! Internal helpers shared by the format readers and writers of mesh/io/: error reporting, the
//! text cursor and number parsing, face fans, index checks, and the output appenders.

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "mesh/tri_mesh.h"

namespace meshquilt::io {

// ---------------------------------------------------------------------------------------------
// Reading

[[noreturn]] inline void parse_fail(const std::string& name, const std::string& problem) {
  throw InputError(name + ": " + problem, ErrorKind::invalid_mesh);
}

// 1-based line number of `at` inside `text`; only computed on the error path.
inline size_t line_of(std::string_view text, const char* at) {
  const size_t offset = static_cast<size_t>(std::max<std::ptrdiff_t>(0, at - text.data()));
  return 1 + static_cast<size_t>(std::count(text.data(), text.data() + std::min(offset, text.size()), '\n'));
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline bool is_space(char c) { return is_blank(c) || c == '\n'; }

// std::from_chars rejects a leading '+', which some writers emit.
inline bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

inline bool parse_int(std::string_view token, int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

// A forward cursor over text; tokens are runs of non-space characters.
struct TextCursor {
  const char* p;
  const char* end;

  bool at_end() const { return p >= end; }
  void skip_blanks() {
    while (p < end && is_blank(*p)) ++p;
  }
  // Skips spaces and newlines, and `#` comments to the end of their line when `comments` is set.
  void skip_space(bool comments) {
    while (p < end) {
      if (is_space(*p)) {
        ++p;
      } else if (comments && *p == '#') {
        skip_line();
      } else {
        break;
      }
    }
  }
  void skip_line() {
    const void* nl = std::memchr(p, '\n', static_cast<size_t>(end - p));
    p = nl ? static_cast<const char*>(nl) + 1 : end;
  }
  // The next token on the current line (empty at end of line or of text).
  std::string_view line_token() {
    skip_blanks();
    const char* start = p;
    while (p < end && !is_space(*p)) ++p;
    return {start, static_cast<size_t>(p - start)};
  }
  // The next token, crossing lines (and comments when `comments` is set).
  std::string_view token(bool comments) {
    skip_space(comments);
    const char* start = p;
    while (p < end && !is_space(*p) && !(comments && *p == '#')) ++p;
    return {start, static_cast<size_t>(p - start)};
  }
};

inline void push_fan(std::vector<Tri>& triangles, const std::vector<int32_t>& polygon) {
  for (size_t i = 1; i + 1 < polygon.size(); ++i) triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
}

// `where` builds the message prefix only on failure: this runs once per face corner.
template <typename Where>
int32_t checked_index(int64_t value, size_t num_vertices, Where&& where) {
  if (value < 0 || static_cast<uint64_t>(value) >= num_vertices) {
    throw InputError(where() + "vertex index " + std::to_string(value) + " outside [0, " +
                     std::to_string(num_vertices) + ")");
  }
  return static_cast<int32_t>(value);
}

// ---------------------------------------------------------------------------------------------
// Writing

inline void append_double(std::string& out, double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);  // shortest round-trip form
  out.append(buffer, end);
}

inline void append_int(std::string& out, int64_t value) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, end);
}

template <typename T>
void append_binary(std::string& out, T value, bool little) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (little != (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

inline void append_vec(std::string& out, const Vec3& p) {
  append_double(out, p.x);
  out += ' ';
  append_double(out, p.y);
  out += ' ';
  append_double(out, p.z);
}

}  // namespace meshquilt::io
