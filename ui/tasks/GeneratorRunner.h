// GeneratorRunner: runs a map generator off the GUI thread for the Generate panel. Every
// request first produces a quick preview at reduced size, then the full-size result, with
// progress; a newer request cancels the older one, so dragging a slider stays live. Both passes
// run on one BackgroundTask.
#pragma once

#include "core/generators/Generators.h"
#include "ui/tasks/BackgroundTask.h"

#include <QObject>
#include <QString>

#include <memory>
#include <vector>

namespace relief::ui::inline tasks {

class GeneratorRunner : public QObject {
  Q_OBJECT

 public:
  explicit GeneratorRunner(QObject* parent = nullptr);

  // The longest side of the quick preview, in texels.
  static constexpr int kPreviewSize = 256;

  // Starts the preview, then the full-size run; cancels what was running.
  void request(core::GeneratorKind kind, std::vector<std::shared_ptr<const core::Image>> inputs,
               core::GeneratorValues values);
  void cancel() { m_task.cancel(); }
  bool isRunning() const { return m_task.isRunning(); }

 Q_SIGNALS:
  void previewReady(const relief::core::GeneratedMap& preview);
  void resultReady(const relief::core::GeneratedMap& result);
  void progress(double fraction);  // of the full-size run
  void failed(const QString& message);

 private:
  struct Job;
  void startFullSize(std::shared_ptr<const Job> job);

  BackgroundTask m_task;
  bool m_fullSize = false;  // the pass in progress reports progress
};

}  // namespace relief::ui::inline tasks
