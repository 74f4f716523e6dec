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

AtomicFileStream::AtomicFileStream(const std::filesystem::path& file, const CancelToken* cancel)
    : name_(file.string()),
      directory_(file.has_parent_path() ? file.parent_path() : std::filesystem::path(".")),
      cancel_(cancel) {
  static std::atomic<uint64_t> counter{0};
  // Same folder as the target, so the rename stays on one file system and is atomic.
  temporary_ = (directory_ / ("." + file.filename().string() + "." + std::to_string(::getpid()) + "." +
                              std::to_string(counter.fetch_add(1)) + ".tmp"))
                   .string();
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) throw IoError(ErrorKind::write_failed, name_ + ": cannot create temporary file: " + std::strerror(errno));
  slot_ = register_pending(temporary_);
}

AtomicFileStream::~AtomicFileStream() {
  if (!temporary_.empty()) discard();
}

void AtomicFileStream::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temporary_.c_str());
  unregister_pending(slot_);
  temporary_.clear();
}

void AtomicFileStream::fail(const std::string& reason) {
  const std::string message = name_ + ": " + reason + ": " + std::strerror(errno);
  discard();
  throw IoError(ErrorKind::write_failed, message);
}

void AtomicFileStream::flush() {
  if (cancel_ && cancel_->cancelled()) {
    discard();
    throw Cancelled();
  }
  if (!write_all(fd_, buffer_.data(), buffer_.size())) fail("write failed");
  buffer_.clear();
}

void AtomicFileStream::write(std::string_view bytes) {
  constexpr size_t kChunk = size_t{4} << 20;
  while (!bytes.empty()) {
    const size_t n = std::min(kChunk - buffer_.size(), bytes.size());
    buffer_.append(bytes.substr(0, n));
    bytes.remove_prefix(n);
    if (buffer_.size() >= kChunk) flush();
  }
}

void AtomicFileStream::commit() {
  flush();
  // The data must be on disk before the rename makes it the file: otherwise a power loss after
  // the rename can leave an empty or partial file under the final name.
  if (::fsync(fd_) != 0) fail("fsync failed");
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close failed");
  if (cancel_ && cancel_->cancelled()) {
    discard();
    throw Cancelled();
  }
  if (::rename(temporary_.c_str(), name_.c_str()) != 0) fail("cannot replace file");
  unregister_pending(slot_);
  temporary_.clear();
  // Persist the rename itself; a folder that cannot be opened or synced (some file systems)
  // does not make the completed write a failure.
  const int dir_fd = ::open(directory_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

void write_file_atomic(const std::filesystem::path& file, std::string_view content, const CancelToken* cancel) {
  write_file_atomic(file, std::span<const std::string_view>(&content, 1), cancel);
}

void write_file_atomic(const std::filesystem::path& file, std::span<const std::string_view> pieces,
                       const CancelToken* cancel) {
  AtomicFileStream stream(file, cancel);
  for (std::string_view piece : pieces) stream.write(piece);
  stream.commit();
}

void remove_pending_temporaries() noexcept {
  for (PendingSlot& slot : g_pending) {
    if (slot.state.load() == kPublished) ::unlink(slot.path);
  }
}

}  // namespace meshquilt
