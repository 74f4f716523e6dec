#include "signals.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>

#include "core/atomic_write.h"

namespace meshquilt::cli {
namespace {

CancelToken g_token;
std::atomic<int> g_signals{0};  // lock-free, so safe to change in a handler

// Only async-signal-safe calls here: an atomic store, unlink (inside
// remove_pending_temporaries), write, signal and raise.
void on_signal(int signal_number) {
  if (g_signals.fetch_add(1) == 0) {
    g_token.cancel();
    return;
  }
  // A second Ctrl-C: the user does not want to wait for the next poll.
  remove_pending_temporaries();
  static const char message[] = "meshquilt: interrupted twice, stopping now\n";
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message, sizeof(message) - 1);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

}  // namespace

CancelToken& interrupt_token() { return g_token; }

void install_interrupt_handlers() {
  static_assert(std::atomic<bool>::is_always_lock_free, "CancelToken must be lock-free to be set from a signal");
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // blocking reads and writes go on; work stops at its next poll
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void check_interrupted() { g_token.check(); }

}  // namespace meshquilt::cli
