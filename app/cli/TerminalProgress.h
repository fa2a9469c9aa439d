// A progress line for relief-cli's long commands (compress, generate, export): "compress
// rock_color.png  42%" redrawn in place on standard error while the work runs, cleared when it
// ends. Only on a terminal: when standard error is a pipe or a file (scripts, logs, CI) or
// under --quiet nothing extra is printed.
#pragma once

#include "core/base/WorkControl.h"

#include <QString>

#include <atomic>
#include <mutex>

namespace relief::cli {

class TerminalProgress {
 public:
  explicit TerminalProgress(QString label);
  ~TerminalProgress();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  // A WorkControl whose progress redraws the line (from any thread; whole percents only).
  core::WorkControl control();
  bool shown() const { return m_enabled; }

 private:
  void draw(double fraction);

  QString m_label;
  bool m_enabled;
  std::mutex m_mutex;
  int m_lastPercent = -1;
};

}  // namespace relief::cli
