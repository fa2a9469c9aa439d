// CompressionRunner: compresses maps off the GUI thread for the Compress panel and the
// "compare all formats" dialog. A run is a list of jobs (a map, its slot, a format and quality),
// done one after another, each on every core; progress covers the whole list, cancel stops at
// the next block row, and each finished job reports its texture, decoded map and metrics. The
// document is never touched: results are previews until the user applies or saves them.
#pragma once

#include "core/compression/CompressionReport.h"
#include "core/compression/Compressor.h"

#include <QFuture>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <vector>

namespace relief::ui {

struct CompressionJob {
  core::MapSlot slot = core::MapSlot::Color;
  std::shared_ptr<const core::Image> map;
  core::CompressionSettings settings;
  double heightScale = 0.05;  // for the height metric
};

struct CompressionOutcome {
  CompressionJob job;
  std::shared_ptr<const core::CompressedTexture> texture;
  std::shared_ptr<const core::Image> decoded;
  core::CompressionReport report;
};

class CompressionRunner : public QObject {
  Q_OBJECT

 public:
  explicit CompressionRunner(QObject* parent = nullptr);
  ~CompressionRunner() override;

  // Starts the jobs; cancels a run in progress first.
  void start(std::vector<CompressionJob> jobs);
  void cancel();
  bool isRunning() const { return m_running; }
  // Blocks until the current run has ended (tests, closing the window).
  void waitForFinished();

 Q_SIGNALS:
  void progress(double fraction, const QString& what);
  void jobFinished(const relief::ui::CompressionOutcome& outcome);
  void finished(const std::vector<relief::ui::CompressionOutcome>& outcomes);
  void cancelled();
  void failed(const QString& message);

 private:
  struct Run;
  void runEnded(const std::shared_ptr<Run>& run);

  QFuture<void> m_future;
  std::shared_ptr<Run> m_run;
  bool m_running = false;
};

}  // namespace relief::ui
