#pragma once
//! SIGINT/SIGTERM handling for the CLI: the first signal cancels the process-wide CancelToken,
//! which long work polls (exit code `interrupted`, temporaries removed by their writers); a
//! second one removes pending temporary files and ends the process at once.

#include "core/error.h"

namespace meshquilt::cli {

//! The token the signal handler cancels; pass it to long work and writers.
CancelToken& interrupt_token();

//! Installs the SIGINT and SIGTERM handlers (sigaction, async-signal-safe bodies). Call once,
//! at the start of main().
void install_interrupt_handlers();

//! \throw Cancelled when a signal has arrived; for the CLI to call between stages.
void check_interrupted();

}  // namespace meshquilt::cli
