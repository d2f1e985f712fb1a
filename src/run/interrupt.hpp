// rupture/run/interrupt.hpp
// SIGINT / SIGTERM end a run cleanly: the handler only records the signal; the driver checks
// after every step, writes a checkpoint and the outputs and stops (status "interrupted").
// A second signal of the same kind acts as usual (the handler is reset when it fires), so a
// run that does not stop can still be killed with a second Ctrl-C.
#pragma once

namespace rupture {

// Installs the handlers for as long as it lives; restores the previous ones after.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// The signal received since the guard was installed (0: none).
int interrupt_signal();

}  // namespace rupture
