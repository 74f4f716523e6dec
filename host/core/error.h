#pragma once
//! Typed errors of meshquilt. Library code throws them where a problem is found, with the file or
//! the parameter and the problem in one line; only the CLI's main catches them and turns them
//! into that line on stderr and an exit code.

#include <atomic>
#include <cctype>
#include <stdexcept>
#include <string>

namespace meshquilt {

//! What went wrong, one kind per distinct failure; the CLI maps each to its exit code
//! (cli/exit_codes.h).
enum class ErrorKind {
  internal,          //!< a bug or an unexpected exception
  file_unreadable,   //!< input file missing or unreadable
  unknown_format,    //!< input file extension/format not supported
  invalid_mesh,      //!< parse error, no faces, NaN/Inf, non-manifold base, degenerate swatch
  invalid_option,    //!< an option value that cannot be honoured (bad pattern, sizes)
  write_failed,      //!< output could not be written
  device,            //!< requested compute device missing or failing
  solver,            //!< a numerical solve failed
  interrupted,       //!< stopped through a CancelToken (a signal, a time limit)
  too_large,         //!< input or job larger than the memory budget or the format allows
  bad_manifest,      //!< a batch manifest that cannot be read as jobs
  batch_incomplete,  //!< a batch or report with jobs that failed or are not done
  bad_texture,       //!< a texture-space file that is truncated, corrupt or inconsistent
  base_mismatch,     //!< a base whose connectivity is not the one a texture was made over
  swatch_unfit,      //!< `swatch check` found a swatch that will not quilt well
};

//! Base of every meshquilt error; carries its kind. Its text may name parameters as {name}, as
//! their options struct names them ("{rows} must be >= 2"): what() reads "rows must be >= 2",
//! and the CLI prints each as its option ("--rows must be >= 2").
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& text) : std::runtime_error(plain(text)), kind_(kind), text_(text) {}
  ErrorKind kind() const { return kind_; }
  //! The message, parameters as {name}.
  const std::string& text() const { return text_; }

  //! `text` with each {name} (lower case, digits and underscores) replaced by spell(name); other
  //! braces are left as they are.
  template <typename Spell>
  static std::string render(std::string text, Spell spell) {
    for (size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open + 1)) {
      size_t close = open + 1;
      while (close < text.size() && (std::islower(static_cast<unsigned char>(text[close])) ||
                                     std::isdigit(static_cast<unsigned char>(text[close])) || text[close] == '_'))
        ++close;
      if (close == open + 1 || close >= text.size() || text[close] != '}' ||
          !std::islower(static_cast<unsigned char>(text[open + 1])))
        continue;
      const std::string name = spell(text.substr(open + 1, close - open - 1));
      text.replace(open, close - open + 1, name);
      open += name.size() - 1;
    }
    return text;
  }

 private:
  static std::string plain(const std::string& text) {
    return render(text, [](const std::string& name) { return name; });
  }

  ErrorKind kind_;
  std::string text_;
};

//! A file could not be read or written. Message: "FILE: problem".
class IoError : public Error {
 public:
  IoError(ErrorKind code, const std::string& message) : Error(code, message) {}
};

//! Input content is invalid (mesh data, option values). Message names the file or option.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message, ErrorKind code = ErrorKind::invalid_mesh)
      : Error(code, message) {}
};

//! A parameter's value cannot be honoured; the text names it as {name} (see Error).
class OptionError : public InputError {
 public:
  explicit OptionError(const std::string& text) : InputError(text, ErrorKind::invalid_option) {}
};

//! The compute device is missing or a device call failed.
class DeviceError : public Error {
 public:
  explicit DeviceError(const std::string& message) : Error(ErrorKind::device, message) {}
};

//! A numerical solve (factorization, max-flow) failed.
class SolverError : public Error {
 public:
  explicit SolverError(const std::string& message) : Error(ErrorKind::solver, message) {}
};

//! The run was cancelled (Ctrl-C, SIGTERM, a batch's time limit) through a CancelToken.
class Cancelled : public Error {
 public:
  Cancelled() : Error(ErrorKind::interrupted, "interrupted") {}
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
