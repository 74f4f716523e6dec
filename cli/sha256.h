#pragma once
//! SHA-256 of files, for batch completion records (the same digest `sha256sum` prints).

#include <filesystem>
#include <string>
#include <string_view>

namespace meshquilt::cli {

//! Lower-case hex SHA-256 (FIPS 180-4) of `bytes`.
std::string sha256_hex(std::string_view bytes);

//! Lower-case hex SHA-256 of a file's content, read in 1 MiB chunks.
//! \throw IoError(file_unreadable) "FILE: cannot open: reason".
std::string sha256_file(const std::filesystem::path& file);

}  // namespace meshquilt::cli
