#pragma once
//! The process's exit codes (docs/cli.md) and the one line an error becomes: the library's error
//! kinds mapped to codes, its parameters named as the command line's options.

#include <string>

#include "core/error.h"

namespace meshquilt::cli {

//! Exit codes, one per kind of failure.
enum class ExitCode : int {
  ok = 0,
  internal = 1,           //!< a bug or an unexpected exception
  usage = 2,              //!< bad command line (unknown option, missing argument)
  file_unreadable = 3,    //!< input file missing or unreadable
  unknown_format = 4,     //!< input file extension/format not supported
  invalid_mesh = 5,       //!< parse error, no faces, NaN/Inf, non-manifold base, degenerate swatch
  invalid_option = 6,     //!< an option value that cannot be honoured (bad pattern, sizes)
  write_failed = 7,       //!< output could not be written
  device = 8,             //!< requested compute device missing or failing
  solver = 9,             //!< a numerical solve failed
  interrupted = 10,       //!< stopped by SIGINT/SIGTERM or a time limit
  too_large = 11,         //!< input or job larger than the memory budget or the format allows
  bad_manifest = 12,      //!< a batch manifest that cannot be read as jobs
  batch_incomplete = 13,  //!< a batch or report with jobs that failed or are not done
  bad_texture = 14,       //!< a texture-space file that is truncated, corrupt or inconsistent
  base_mismatch = 15,     //!< a base whose connectivity is not the one a texture was made over
  swatch_unfit = 16,      //!< `swatch check` found open, cut or intersecting elements, or a thick layout
};

//! The exit code of an error kind.
int exit_code(ErrorKind kind);

//! `text` with each parameter named as {name} written as its option: {max_memory} -> --max-memory.
std::string with_options(const std::string& text);

//! An error's message as the command line reports it (without the "meshquilt: " prefix).
inline std::string message(const Error& e) { return with_options(e.text()); }

}  // namespace meshquilt::cli
