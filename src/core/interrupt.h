// A user interruption (Ctrl-C in `sinew run`): the signal handler only sets a
// flag; iterative loops that can run long (CG iterations) stop at the next
// iteration, the current step finishes and the command line reports and exits.
#pragma once

namespace sinew {

// Async-signal-safe (a lock-free atomic store).
void request_interrupt() noexcept;
bool interrupt_requested() noexcept;
void clear_interrupt() noexcept;

}  // namespace sinew
