// CompressionRunner; see CompressionRunner.h.
#include "ui/CompressionRunner.h"

#include "ui/QtText.h"

#include <QElapsedTimer>
#include <QMetaObject>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

#include <mutex>

namespace relief::ui {

// Shared between the GUI thread and the worker; outlives the runner if the worker is late.
struct CompressionRunner::Run {
  std::vector<CompressionJob> jobs;
  std::atomic<bool> cancel{false};
  std::mutex mutex;
  std::vector<CompressionOutcome> outcomes;
  std::string error;
};

CompressionRunner::CompressionRunner(QObject* parent) : QObject(parent) {}

CompressionRunner::~CompressionRunner() {
  cancel();
  m_future.waitForFinished();
}

// On the GUI thread, after the worker returned. A run replaced by a newer one says nothing.
void CompressionRunner::runEnded(const std::shared_ptr<Run>& run) {
  if (run != m_run)
    return;
  m_running = false;
  if (run->cancel.load()) {
    Q_EMIT cancelled();
  } else if (!run->error.empty()) {
    Q_EMIT failed(QString::fromStdString(run->error));
  } else {
    Q_EMIT finished(run->outcomes);
  }
}

void CompressionRunner::cancel() {
  if (m_run)
    m_run->cancel.store(true);
}

void CompressionRunner::waitForFinished() {
  m_future.waitForFinished();
}

void CompressionRunner::start(std::vector<CompressionJob> jobs) {
  cancel();
  m_future.waitForFinished();  // the previous run stops within one block row
  auto run = std::make_shared<Run>();
  run->jobs = std::move(jobs);
  m_run = run;
  m_running = true;
  QPointer<CompressionRunner> self(this);
  m_future = QtConcurrent::run([run, self] {
    const auto ended = [&run, &self] {
      QMetaObject::invokeMethod(
          self,
          [self, run] {
            if (self)
              self->runEnded(run);
          },
          Qt::QueuedConnection);
    };
    double totalPixels = 0.0;
    for (const CompressionJob& job : run->jobs)
      totalPixels += double(job.map->pixelCount());
    double donePixels = 0.0;
    for (const CompressionJob& job : run->jobs) {
      const double share = double(job.map->pixelCount()) / std::max(totalPixels, 1.0);
      const double begin = donePixels / std::max(totalPixels, 1.0);
      const QString what = QStringLiteral("%1 → %2").arg(
          toQString(core::mapSlotLabel(job.slot)),
          toQString(core::textureFormatInfo(job.settings.format).label));
      core::WorkControl control;
      control.cancel = &run->cancel;
      control.progress = [self, begin, share, what](double fraction) {
        QMetaObject::invokeMethod(
            self,
            [self, fraction = begin + share * fraction, what] {
              if (self)
                Q_EMIT self->progress(fraction, what);
            },
            Qt::QueuedConnection);
      };
      QElapsedTimer timer;
      timer.start();
      core::Result<core::CompressedTexture> texture =
          core::compressMap(*job.map, job.slot, job.settings, control);
      const double seconds = double(timer.nsecsElapsed()) * 1e-9;
      if (run->cancel.load())
        return ended();
      if (!texture) {
        run->error = std::string(core::mapSlotLabel(job.slot)) + ": " + texture.error();
        return ended();
      }
      CompressionOutcome outcome;
      outcome.job = job;
      auto decoded = std::make_shared<core::Image>(core::decodeAsMap(texture.value()).value());
      outcome.report = core::makeCompressionReport(*job.map, *decoded, job.slot, job.heightScale);
      outcome.report.format = job.settings.format;
      outcome.report.encodeSeconds = seconds;
      outcome.report.size =
          core::measureSize(job.settings.format, job.map->channels(), texture->byteSize());
      outcome.texture = std::make_shared<core::CompressedTexture>(std::move(texture).value());
      outcome.decoded = std::move(decoded);
      {
        std::lock_guard lock(run->mutex);
        run->outcomes.push_back(outcome);
      }
      QMetaObject::invokeMethod(
          self,
          [self, outcome] {
            if (self)
              Q_EMIT self->jobFinished(outcome);
          },
          Qt::QueuedConnection);
      donePixels += double(job.map->pixelCount());
    }
    ended();
  });
}

}  // namespace relief::ui
