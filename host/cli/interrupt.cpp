#include "interrupt.h"

#include <csignal>

namespace prism_cli {
namespace {

volatile std::sig_atomic_t g_requested = 0;

using Handler = void (*)(int);
Handler g_previous = SIG_DFL;

extern "C" void onInterrupt(int) {
  g_requested = 1;
  // The next Ctrl-C must work even if the render never checks in again.
  std::signal(SIGINT, SIG_DFL);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_requested = 0;
  g_previous = std::signal(SIGINT, onInterrupt);
  if (g_previous == SIG_ERR) g_previous = SIG_DFL;
}

InterruptGuard::~InterruptGuard() { std::signal(SIGINT, g_previous); }

bool InterruptGuard::requested() { return g_requested != 0; }

}  // namespace prism_cli
