#pragma once
//! Typed errors of meshquilt. Library code throws them where a problem is found; only the CLI's
//! main catches them and turns them into one line on stderr and the exit code below.

#include <atomic>
#include <stdexcept>
#include <string>

namespace meshquilt {

//! Process exit codes, one per kind of failure (documented in the README).
enum class ExitCode : int {
  ok = 0,
  internal = 1,        //!< a bug or an unexpected exception
  usage = 2,           //!< bad command line (unknown option, missing argument)
  file_unreadable = 3, //!< input file missing or unreadable
  unknown_format = 4,  //!< input file extension/format not supported
  invalid_mesh = 5,    //!< parse error, no faces, NaN/Inf, non-manifold base, degenerate swatch
  invalid_option = 6,  //!< an option value that cannot be honoured (bad pattern, sizes)
  write_failed = 7,    //!< output could not be written
  device = 8,          //!< requested compute device missing or failing
  solver = 9,          //!< a numerical solve failed
  interrupted = 10,    //!< stopped by SIGINT/SIGTERM or a time limit through a CancelToken
  too_large = 11,      //!< input or job larger than the memory budget (--max-memory) or the format allows
  bad_manifest = 12,   //!< a batch manifest that cannot be read as jobs (syntax, unknown option, duplicates)
  batch_incomplete = 13, //!< a batch or report with jobs that failed or are not done
  bad_texture = 14,    //!< a texture-space file that is truncated, corrupt or inconsistent
  base_mismatch = 15,  //!< a base whose connectivity is not the one a texture was made over
};

//! Base of every meshquilt error; carries its exit code.
class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

//! A file could not be read or written. Message: "FILE: problem".
class IoError : public Error {
 public:
  IoError(ExitCode code, const std::string& message) : Error(code, message) {}
};

//! Input content is invalid (mesh data, option values). Message names the file or option.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message, ExitCode code = ExitCode::invalid_mesh)
      : Error(code, message) {}
};

//! The compute device is missing or a device call failed.
class DeviceError : public Error {
 public:
  explicit DeviceError(const std::string& message) : Error(ExitCode::device, message) {}
};

//! A numerical solve (factorization, max-flow) failed.
class SolverError : public Error {
 public:
  explicit SolverError(const std::string& message) : Error(ExitCode::solver, message) {}
};

//! The run was cancelled (Ctrl-C, SIGTERM, a batch's time limit) through a CancelToken.
class Cancelled : public Error {
 public:
  Cancelled() : Error(ExitCode::interrupted, "interrupted") {}
};

//! Shared flag that long work polls between stages and inside long loops; setting it from a
//! signal handler is safe (a lock-free atomic).
class CancelToken {
 public:
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  //! \throw Cancelled once cancel() has been called.
  void check() const {
    if (cancelled()) throw Cancelled();
  }

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace meshquilt
