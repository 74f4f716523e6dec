#pragma once
//! Crash-safe file replacement: every output of meshquilt (meshes, stats JSON) goes through
//! write_file_atomic, so a process stopped at any moment (SIGKILL included) leaves either the old
//! file or the complete new one.

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace meshquilt {

class CancelToken;

//! Writes `content` to a new temporary file in `file`'s folder (".NAME.PID.N.tmp"), fsyncs it,
//! renames it over `file` and fsyncs the folder. While it exists the temporary file is listed
//! for remove_pending_temporaries(). `cancel`, when given, is polled between 4 MiB chunks and
//! before the rename.
//! \throw IoError(write_failed) "FILE: problem" on any failure (the temporary file is removed
//!        first); Cancelled when `cancel` fires (the temporary file is removed, `file` untouched).
void write_file_atomic(const std::filesystem::path& file, std::string_view content,
                       const CancelToken* cancel = nullptr);
//! The same, with the content given as pieces written one after another.
void write_file_atomic(const std::filesystem::path& file, std::span<const std::string_view> pieces,
                       const CancelToken* cancel = nullptr);

//! A file written piece by piece and replaced atomically, as write_file_atomic does: for outputs
//! too large to hold. Destroyed before commit(), it removes its temporary file and leaves `file`
//! untouched.
class AtomicFileStream {
 public:
  //! \throw IoError(write_failed) when the temporary file cannot be created.
  explicit AtomicFileStream(const std::filesystem::path& file, const CancelToken* cancel = nullptr);
  ~AtomicFileStream();
  AtomicFileStream(const AtomicFileStream&) = delete;
  AtomicFileStream& operator=(const AtomicFileStream&) = delete;
  //! Appends `bytes` (buffered). \throw IoError(write_failed); Cancelled when `cancel` fires.
  void write(std::string_view bytes);
  //! Flushes, fsyncs and renames the file into place. \throw as write().
  void commit();

 private:
  void flush();
  void fail(const std::string& reason);
  void discard() noexcept;
  std::string name_, temporary_, buffer_;
  std::filesystem::path directory_;
  const CancelToken* cancel_;
  int fd_ = -1, slot_ = -1;
};

//! Unlinks every temporary file write_file_atomic is writing now. Async-signal-safe: meant for
//! a signal handler that is about to end the process.
void remove_pending_temporaries() noexcept;

}  // namespace meshquilt
