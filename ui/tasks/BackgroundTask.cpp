// BackgroundTask; see BackgroundTask.h.
#include "ui/tasks/BackgroundTask.h"

#include <QMetaObject>

namespace relief::ui::inline tasks {

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {}

BackgroundTask::~BackgroundTask() {
  cancel();
  waitForFinished();
}

std::shared_ptr<BackgroundTask::Run> BackgroundTask::begin() {
  if (m_current)
    m_current->cancel.store(true);  // replaced: its result is dropped, no signal
  m_current = std::make_shared<Run>();
  return m_current;
}

core::WorkControl BackgroundTask::controlFor(const std::shared_ptr<Run>& run) {
  core::WorkControl control;
  control.cancel = &run->cancel;  // the Run lives as long as the work's copy of `run`
  control.progress = [this, run](double fraction) {
    QMetaObject::invokeMethod(
        this,
        [this, run, fraction] {
          if (run == m_current && !run->cancel.load())
            Q_EMIT progress(fraction);
        },
        Qt::QueuedConnection);
  };
  return control;
}

bool BackgroundTask::end(const std::shared_ptr<Run>& run) {
  if (run != m_current)
    return false;
  m_current.reset();
  if (run->cancel.load()) {
    Q_EMIT cancelled();
    Q_EMIT finished();
    return false;
  }
  return true;
}

void BackgroundTask::cancel() {
  if (m_current)
    m_current->cancel.store(true);
}

void BackgroundTask::track(QFuture<void> future) {
  m_futures.removeIf([](const QFuture<void>& done) { return done.isFinished(); });
  m_futures.append(std::move(future));
}

void BackgroundTask::waitForFinished() {
  for (QFuture<void>& future : m_futures)
    future.waitForFinished();
  m_futures.clear();
}

}  // namespace relief::ui::inline tasks
