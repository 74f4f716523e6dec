#include "core/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "core/error.h"

namespace meshquilt {
namespace {

std::atomic<uint64_t> g_budget{0};  // 0: the default

// A cgroup file holds a byte count, or "max" (v2) / a huge number (v1) when there is no limit.
uint64_t read_limit_file(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text)) return std::numeric_limits<uint64_t>::max();
  uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value == 0) return std::numeric_limits<uint64_t>::max();
  return value;
}

uint64_t compute_limit() {
  uint64_t limit = std::numeric_limits<uint64_t>::max();
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page_size > 0) limit = static_cast<uint64_t>(pages) * static_cast<uint64_t>(page_size);
  limit = std::min(limit, read_limit_file("/sys/fs/cgroup/memory.max"));
  limit = std::min(limit, read_limit_file("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit rl{};
    if (getrlimit(resource, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY) {
      limit = std::min<uint64_t>(limit, static_cast<uint64_t>(rl.rlim_cur));
    }
  }
  // No source answered (an unusual system): assume a modest machine rather than none.
  if (limit == std::numeric_limits<uint64_t>::max()) limit = uint64_t{8} << 30;
  return limit;
}

}  // namespace

uint64_t memory_limit_bytes() {
  static const uint64_t limit = compute_limit();
  return limit;
}

uint64_t default_memory_budget() { return memory_limit_bytes() / 4 * 3; }

void set_memory_budget(uint64_t bytes) { g_budget.store(bytes); }

uint64_t memory_budget() {
  const uint64_t set = g_budget.load();
  return set != 0 ? set : default_memory_budget();
}

uint64_t parse_memory_size(const std::string& text, const std::string& option) {
  auto fail = [&] {
    throw OptionError("{" + option + "}: expected a size such as 8G, 512M or 1.5GiB, got '" + text + "'");
  };
  double number = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto [rest, ec] = std::from_chars(begin, end, number);
  if (ec != std::errc() || rest == begin || !(number > 0.0)) fail();
  std::string unit(rest, end);
  std::transform(unit.begin(), unit.end(), unit.begin(), [](unsigned char c) { return std::tolower(c); });
  if (unit.size() > 1 && unit.back() == 'b') unit.pop_back();      // "GB", "GiB"
  if (unit.size() > 1 && unit.back() == 'i') unit.pop_back();      // "Gi"
  double scale = 1.0;
  if (unit == "" || unit == "b") {
    scale = 1.0;
  } else if (unit == "k") {
    scale = 1024.0;
  } else if (unit == "m") {
    scale = 1024.0 * 1024.0;
  } else if (unit == "g") {
    scale = 1024.0 * 1024.0 * 1024.0;
  } else if (unit == "t") {
    scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
  } else {
    fail();
  }
  const double bytes = number * scale;
  if (!(bytes >= 1.0 && bytes < 1.8e19)) fail();
  return static_cast<uint64_t>(bytes);
}

std::string format_bytes(double bytes) {
  static const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  char buffer[64];
  if (unit == 0) {
    std::snprintf(buffer, sizeof(buffer), "%.0f B", bytes);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%.1f %s", bytes, units[unit]);
  }
  return buffer;
}

void check_memory_budget(double bytes, const std::string& what) {
  const uint64_t budget = memory_budget();
  if (!(bytes <= static_cast<double>(budget))) {
    throw InputError(what + " needs about " + format_bytes(bytes) + ", more than the memory budget " +
                         format_bytes(static_cast<double>(budget)) + " (raise it with {max_memory})",
                     ErrorKind::too_large);
  }
}

}  // namespace meshquilt
