#include "core/atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include "core/error.h"

namespace meshquilt {
namespace {

// Temporary files in progress, for remove_pending_temporaries(). A fixed table of fixed buffers:
// a signal handler may read it at any moment, so nothing here allocates or locks. A slot goes
// free -> claimed (path being copied) -> published; the handler only reads published slots.
constexpr int kSlots = 16;
constexpr size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kClaimed = 1, kPublished = 2 };
struct PendingSlot {
  std::atomic<int> state{kFree};
  char path[kPathBytes];
};
PendingSlot g_pending[kSlots];

int register_pending(const std::string& path) {
  if (path.size() + 1 > kPathBytes) return -1;
  for (int slot = 0; slot < kSlots; ++slot) {
    int expected = kFree;
    if (!g_pending[slot].state.compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(g_pending[slot].path, path.c_str(), path.size() + 1);
    g_pending[slot].state.store(kPublished);
    return slot;
  }
  return -1;  // table full: the file is still written safely, only not removed by a signal
}

void unregister_pending(int slot) {
  if (slot >= 0) g_pending[slot].state.store(kFree);
}

// Writes every byte, retrying short writes and EINTR.
bool write_all(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

void write_file_atomic(const std::filesystem::path& file, std::string_view content, const CancelToken* cancel) {
  write_file_atomic(file, std::span<const std::string_view>(&content, 1), cancel);
}

void write_file_atomic(const std::filesystem::path& file, std::span<const std::string_view> pieces,
                       const CancelToken* cancel) {
  const std::string name = file.string();
  static std::atomic<uint64_t> counter{0};
  const std::filesystem::path directory = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  // Same folder as the target, so the rename stays on one file system and is atomic.
  const std::string temporary = (directory / ("." + file.filename().string() + "." + std::to_string(::getpid()) + "." +
                                              std::to_string(counter.fetch_add(1)) + ".tmp"))
                                    .string();
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw IoError(ErrorKind::write_failed, name + ": cannot create temporary file: " + std::strerror(errno));
  const int slot = register_pending(temporary);
  int open_fd = fd;
  auto discard = [&] {
    if (open_fd >= 0) ::close(open_fd);
    open_fd = -1;
    ::unlink(temporary.c_str());
    unregister_pending(slot);
  };
  auto fail = [&](const std::string& reason) {
    const std::string message = name + ": " + reason + ": " + std::strerror(errno);
    discard();
    throw IoError(ErrorKind::write_failed, message);
  };
  auto poll = [&] {
    if (cancel && cancel->cancelled()) {
      discard();
      throw Cancelled();
    }
  };
  constexpr size_t kChunk = size_t{4} << 20;
  for (std::string_view content : pieces)
    for (size_t offset = 0; offset < content.size(); offset += kChunk) {
      poll();
      const size_t n = std::min(kChunk, content.size() - offset);
      if (!write_all(fd, content.data() + offset, n)) fail("write failed");
    }
  // The data must be on disk before the rename makes it the file: otherwise a power loss after
  // the rename can leave an empty or partial file under the final name.
  if (::fsync(fd) != 0) fail("fsync failed");
  open_fd = -1;
  if (::close(fd) != 0) {
    const std::string message = name + ": close failed: " + std::strerror(errno);
    discard();
    throw IoError(ErrorKind::write_failed, message);
  }
  poll();
  if (::rename(temporary.c_str(), name.c_str()) != 0) fail("cannot replace file");
  unregister_pending(slot);
  // Persist the rename itself; a folder that cannot be opened or synced (some file systems)
  // does not make the completed write a failure.
  const int dir_fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

void remove_pending_temporaries() noexcept {
  for (PendingSlot& slot : g_pending) {
    if (slot.state.load() == kPublished) ::unlink(slot.path);
  }
}

}  // namespace meshquilt
