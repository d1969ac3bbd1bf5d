#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace prism_cli {
namespace {

constexpr double kQuietSeconds = 1.0;
constexpr double kRedrawSeconds = 0.1;
constexpr int kBarWidth = 30;

}  // namespace

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) == 1; }

ProgressBar::ProgressBar(bool enabled) : m_enabled(enabled), m_start(Clock::now()) {}

void ProgressBar::update(double fraction_done) {
  if (!m_enabled) return;
  std::lock_guard<std::mutex> lock(m_mutex);
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - m_start).count();
  if (elapsed <= kQuietSeconds) return;
  if (m_drawn && std::chrono::duration<double>(now - m_last_draw).count() < kRedrawSeconds) return;
  m_last_draw = now;
  draw(fraction_done, elapsed);
}

void ProgressBar::draw(double fraction_done, double elapsed) {
  const double fraction = std::isfinite(fraction_done) ? std::clamp(fraction_done, 0.0, 1.0) : 0.0;
  const int filled = static_cast<int>(fraction * kBarWidth);
  std::string bar(static_cast<size_t>(filled), '#');
  bar.resize(kBarWidth, '.');
  char remaining[48] = "";
  // A linear estimate; only shown once there is enough done to extrapolate from.
  if (fraction >= 0.02 && fraction < 1.0) {
    const double left = elapsed * (1.0 - fraction) / fraction;
    std::snprintf(remaining, sizeof remaining, left < 10.0 ? ", about %.1f s left" : ", about %.0f s left", left);
  }
  std::fprintf(stderr, "\rprism: rendering [%s] %3d%%  %.1f s%s\033[K", bar.c_str(),
               static_cast<int>(fraction * 100.0), elapsed, remaining);
  std::fflush(stderr);
  m_drawn = true;
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(m_mutex);
  if (!m_drawn) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  m_drawn = false;
}

}  // namespace prism_cli
