#pragma once
//! Writes a small text file atomically (write_file_atomic: temporary file beside it, fsync, rename).

#include <filesystem>
#include <string>

namespace meshquilt::cli {

//! \throw IoError(write_failed) naming the file.
void write_text_atomic(const std::filesystem::path& file, const std::string& text);

//! Fails early, before long work, when `file` could not be written later: its folder is missing
//! or not writable. \throw IoError(write_failed) naming the file.
void check_writable(const std::filesystem::path& file);

}  // namespace meshquilt::cli
