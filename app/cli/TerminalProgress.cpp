// TerminalProgress; see TerminalProgress.h.
#include "TerminalProgress.h"

#include "CliCommon.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace relief::cli {

TerminalProgress::TerminalProgress(QString label)
    : m_label(std::move(label)), m_enabled(!quiet() && isatty(STDERR_FILENO) == 1) {}

TerminalProgress::~TerminalProgress() {
  if (m_enabled && m_lastPercent >= 0) {
    // Erase the line so what follows (the result, an error) starts clean.
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }
}

core::WorkControl TerminalProgress::control() {
  core::WorkControl control;
  if (m_enabled)
    control.progress = [this](double fraction) { draw(fraction); };
  return control;
}

void TerminalProgress::draw(double fraction) {
  const int percent = std::clamp(int(std::floor(fraction * 100.0)), 0, 100);
  const std::lock_guard<std::mutex> lock(m_mutex);
  if (percent == m_lastPercent)
    return;
  m_lastPercent = percent;
  constexpr int kBarWidth = 24;
  const int filled = percent * kBarWidth / 100;
  const QByteArray label = m_label.toLocal8Bit();
  std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%", label.constData(), filled,
               "########################", kBarWidth - filled, "", percent);
  std::fflush(stderr);
}

}  // namespace relief::cli
