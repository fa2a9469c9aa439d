// GeneratorRunner; see GeneratorRunner.h.
#include "ui/GeneratorRunner.h"

#include "core/generators/ImageFilters.h"

#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace relief::ui {

struct GeneratorRunner::Job {
  core::GeneratorKind kind;
  std::vector<std::shared_ptr<const core::Image>> inputs;
  core::GeneratorValues values;
};

namespace {

using Outcome = core::Result<core::GeneratedMap>;

}  // namespace

GeneratorRunner::GeneratorRunner(QObject* parent) : QObject(parent) {
  connect(&m_previewWatcher, &QFutureWatcher<Outcome>::finished, this, [this] {
    if (m_previewWatcher.isCanceled())
      return;
    const Outcome outcome = m_previewWatcher.result();
    if (outcome.ok())
      Q_EMIT previewReady(outcome.value());
    startFullSize();
  });
  connect(&m_fullWatcher, &QFutureWatcher<Outcome>::finished, this, [this] {
    if (m_fullWatcher.isCanceled())
      return;
    m_running = false;
    const Outcome outcome = m_fullWatcher.result();
    if (outcome.ok()) {
      Q_EMIT resultReady(outcome.value());
    } else if (outcome.error() != "cancelled") {
      Q_EMIT failed(QString::fromStdString(outcome.error()));
    }
  });
}

GeneratorRunner::~GeneratorRunner() {
  cancel();
  m_previewWatcher.waitForFinished();
  m_fullWatcher.waitForFinished();
}

void GeneratorRunner::cancel() {
  if (m_cancel)
    m_cancel->store(true);
  m_running = false;
}

void GeneratorRunner::request(core::GeneratorKind kind,
                              std::vector<std::shared_ptr<const core::Image>> inputs,
                              core::GeneratorValues values) {
  cancel();
  m_cancel = std::make_shared<std::atomic<bool>>(false);
  m_job = std::make_shared<Job>(Job{kind, std::move(inputs), std::move(values)});
  m_running = true;
  // The previews of the inputs, at most kPreviewSize on their longer side.
  auto job = m_job;
  auto cancelFlag = m_cancel;
  m_previewWatcher.setFuture(QtConcurrent::run([job, cancelFlag]() -> Outcome {
    const core::Image& first = *job->inputs.front();
    const double scale =
        std::min(1.0, double(kPreviewSize) / std::max(first.width(), first.height()));
    std::vector<core::Image> small;
    std::vector<const core::Image*> pointers;
    small.reserve(job->inputs.size());
    for (const auto& input : job->inputs) {
      if (scale < 1.0) {
        small.push_back(core::resizeImage(*input,
                                          std::max(1, int(std::lround(input->width() * scale))),
                                          std::max(1, int(std::lround(input->height() * scale)))));
        pointers.push_back(&small.back());
      } else {
        pointers.push_back(input.get());
      }
    }
    core::WorkControl control;
    control.cancel = cancelFlag.get();
    return core::runGenerator({job->kind, pointers, job->values, scale}, control);
  }));
}

void GeneratorRunner::startFullSize() {
  if (!m_job || !m_cancel || m_cancel->load())
    return;
  auto job = m_job;
  auto cancelFlag = m_cancel;
  QPointer<GeneratorRunner> self(this);
  m_fullWatcher.setFuture(QtConcurrent::run([job, cancelFlag, self]() -> Outcome {
    std::vector<const core::Image*> pointers;
    for (const auto& input : job->inputs)
      pointers.push_back(input.get());
    core::WorkControl control;
    control.cancel = cancelFlag.get();
    control.progress = [self, cancelFlag](double fraction) {
      if (cancelFlag->load())
        return;
      QMetaObject::invokeMethod(
          self,
          [self, fraction] {
            if (self)
              Q_EMIT self->progress(fraction);
          },
          Qt::QueuedConnection);
    };
    return core::runGenerator({job->kind, pointers, job->values, 1.0}, control);
  }));
}

}  // namespace relief::ui
