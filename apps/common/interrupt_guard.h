// SIGINT and SIGTERM as a request to stop, for commands that write output over a long run: while an
// InterruptGuard lives, the signals set a flag that the run polls between units of work, so that it can
// stop and let its destructors remove the partial output instead of dying with it half-written.
#pragma once
#include <csignal>

namespace lagoon::cli {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal received (SIGINT or SIGTERM), 0 if none.
  int signal() const;
  // The shell's convention for a run ended by `signal()`: 128 + its number.
  int exit_code() const { return 128 + signal(); }

 private:
  struct sigaction old_int_ {
  }, old_term_{};
};

}  // namespace lagoon::cli
