// A one-line progress bar on stderr for long renders. It stays silent for the first
// second (short renders print nothing), redraws at most ten times a second, and erases
// itself when done, so the terminal keeps only the summary.
#pragma once

#include <chrono>
#include <mutex>

namespace prism_cli {

class ProgressBar {
 public:
  // `enabled` false makes every call a no-op (not a terminal, or --quiet).
  explicit ProgressBar(bool enabled);
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // May be called from any thread, as often as the renderer likes.
  void update(double fraction_done);
  // Erases the line if anything was drawn.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(double fraction_done, double elapsed_seconds);

  bool m_enabled;
  bool m_drawn = false;
  Clock::time_point m_start;
  Clock::time_point m_last_draw;
  std::mutex m_mutex;
};

// True when stderr is an interactive terminal.
bool stderrIsTerminal();

}  // namespace prism_cli
