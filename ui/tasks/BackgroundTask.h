// BackgroundTask: the one way the editor runs work off the GUI thread — compression,
// generation, the cone map, the error view's exact trace, export, the preset library's
// thumbnails and saves, and autosave. run() starts the work on Qt's thread pool with a
// WorkControl (a cancel flag the work polls, a progress callback); a newer run() cancels the
// older, whose result is then dropped; progress and the result come back on the GUI thread, to
// the caller's callbacks, for the newest run only. The callback is where a result enters the
// document, as one undo command. Destroying the task cancels the work and waits for it, so a
// callback never outlives its owner.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"

#include <QFuture>
#include <QList>
#include <QObject>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <functional>
#include <memory>

namespace relief::ui::inline tasks {

class BackgroundTask : public QObject {
  Q_OBJECT

 public:
  explicit BackgroundTask(QObject* parent = nullptr);
  ~BackgroundTask() override;

  template <class T>
  using Work = std::function<T(const core::WorkControl& control)>;
  template <class T>
  using Done = std::function<void(T&& result)>;

  // Starts `work`; `done` receives its result on the GUI thread unless the run was cancelled or
  // replaced by a newer one (then `cancelled` is emitted, or nothing).
  template <class T>
  void run(Work<T> work, Done<T> done);

  void cancel();  // the newest run stops at its next check; `cancelled` follows
  bool isRunning() const { return m_current != nullptr; }
  // Blocks until every run has returned (tests; owners about to go away).
  void waitForFinished();

 Q_SIGNALS:
  void progress(double fraction);  // 0..1, of the newest run
  void cancelled();
  void finished();  // after `done` or `cancelled`: the task is idle again

 private:
  struct Run {
    std::atomic<bool> cancel{false};
  };
  std::shared_ptr<Run> begin();
  core::WorkControl controlFor(const std::shared_ptr<Run>& run);
  // On the GUI thread, when `run` returned: true when it is still the newest and was not
  // cancelled (its result is wanted); ends it either way.
  bool end(const std::shared_ptr<Run>& run);
  void track(QFuture<void> future);

  std::shared_ptr<Run> m_current;
  QList<QFuture<void>> m_futures;  // runs still on the pool, the replaced ones included
};

template <class T>
void BackgroundTask::run(Work<T> work, Done<T> done) {
  std::shared_ptr<Run> run = begin();
  const core::WorkControl control = controlFor(run);
  track(QtConcurrent::run([this, run, control, work = std::move(work), done = std::move(done)] {
    auto result = std::make_shared<T>(work(control));
    // `this` outlives the work (the destructor waits); a queued call to a deleted context is
    // dropped by Qt.
    QMetaObject::invokeMethod(
        this,
        [this, run, result, done] {
          if (!end(run))
            return;
          done(std::move(*result));
          if (!m_current)  // unless `done` started the next run (a preview's full-size pass)
            Q_EMIT finished();
        },
        Qt::QueuedConnection);
  }));
}

}  // namespace relief::ui::inline tasks
