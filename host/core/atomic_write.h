#pragma once
//! Crash-safe file replacement: every output of meshquilt (meshes, stats JSON) goes through
//! write_file_atomic, so a process stopped at any moment (SIGKILL included) leaves either the old
//! file or the complete new one.

#include <filesystem>
#include <span>
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

//! Unlinks every temporary file write_file_atomic is writing now. Async-signal-safe: meant for
//! a signal handler that is about to end the process.
void remove_pending_temporaries() noexcept;

}  // namespace meshquilt
