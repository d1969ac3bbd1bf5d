// Ctrl-C during a render: the first SIGINT asks the render to stop (through the
// progress callback's cancel result), so the program exits cleanly without writing a
// half image; a second SIGINT kills the process as usual.
#pragma once

namespace prism_cli {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handler
  ~InterruptGuard();  // restores the previous one
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static bool requested();
};

}  // namespace prism_cli
