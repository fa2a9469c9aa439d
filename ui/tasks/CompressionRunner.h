// CompressionRunner: compresses maps off the GUI thread for the Compress panel and the
// "compare all formats" dialog. A run is a list of core compression jobs (CompressionJob.h), done
// one after another, each on every core; progress covers the whole list, cancel stops at the
// next block row, a newer run replaces the older (BackgroundTask), and each finished job reports
// its texture, decoded map and metrics. The document is never touched: results are previews
// until the user applies or saves them.
#pragma once

#include "core/compression/CompressionJob.h"
#include "ui/tasks/BackgroundTask.h"

#include <QObject>
#include <QString>

#include <vector>

namespace relief::ui::inline tasks {

class CompressionRunner : public QObject {
  Q_OBJECT

 public:
  explicit CompressionRunner(QObject* parent = nullptr);

  // Starts the jobs; cancels a run in progress first.
  void start(std::vector<core::CompressionJob> jobs);
  void cancel() { m_task.cancel(); }
  bool isRunning() const { return m_task.isRunning(); }
  // Blocks until the current run has returned (tests, closing the window).
  void waitForFinished() { m_task.waitForFinished(); }

 Q_SIGNALS:
  void progress(double fraction, const QString& what);
  void jobFinished(const relief::core::CompressionOutcome& outcome);
  void finished(const std::vector<relief::core::CompressionOutcome>& outcomes);
  void cancelled();
  void failed(const QString& message);

 private:
  BackgroundTask m_task;
  QString m_what;  // the job in progress, for the progress text
};

}  // namespace relief::ui::inline tasks
