// CompressionRunner; see CompressionRunner.h.
#include "ui/tasks/CompressionRunner.h"

#include "ui/QtText.h"

#include <QMetaObject>

#include <algorithm>

namespace relief::ui::inline tasks {
namespace {

QString jobText(const core::CompressionJob& job) {
  return QStringLiteral("%1 → %2").arg(
      toQString(core::mapSlotLabel(job.slot)),
      toQString(core::textureFormatInfo(job.settings.format).label));
}

// What a run hands back: every outcome, or the first failure (naming the map's slot).
using Outcomes = core::Result<std::vector<core::CompressionOutcome>>;

}  // namespace

CompressionRunner::CompressionRunner(QObject* parent) : QObject(parent) {
  connect(&m_task, &BackgroundTask::progress, this,
          [this](double fraction) { Q_EMIT progress(fraction, m_what); });
  connect(&m_task, &BackgroundTask::cancelled, this, &CompressionRunner::cancelled);
}

void CompressionRunner::start(std::vector<core::CompressionJob> jobs) {
  // Each job's share of the progress is its share of the texels.
  double totalPixels = 0.0;
  for (const core::CompressionJob& job : jobs)
    totalPixels += double(job.map->pixelCount());
  totalPixels = std::max(totalPixels, 1.0);
  m_what = jobs.empty() ? QString() : jobText(jobs.front());
  m_task.run<Outcomes>(
      [this, jobs = std::move(jobs), totalPixels](const core::WorkControl& control) -> Outcomes {
        std::vector<core::CompressionOutcome> outcomes;
        double donePixels = 0.0;
        for (const core::CompressionJob& job : jobs) {
          const double begin = donePixels / totalPixels;
          const double share = double(job.map->pixelCount()) / totalPixels;
          QMetaObject::invokeMethod(
              this, [this, what = jobText(job)] { m_what = what; }, Qt::QueuedConnection);
          core::WorkControl part;
          part.cancel = control.cancel;
          part.progress = [&control, begin, share](double f) { control.report(begin + share * f); };
          core::Result<core::CompressionOutcome> outcome = core::runCompressionJob(job, part);
          if (control.cancelled())
            return core::makeError("cancelled");
          if (!outcome)
            return core::makeError(std::string(core::mapSlotLabel(job.slot)) + ": " +
                                   outcome.error());
          QMetaObject::invokeMethod(
              this, [this, finished = outcome.value()] { Q_EMIT jobFinished(finished); },
              Qt::QueuedConnection);
          outcomes.push_back(std::move(outcome).value());
          donePixels += double(job.map->pixelCount());
        }
        return outcomes;
      },
      [this](Outcomes&& outcomes) {
        if (outcomes)
          Q_EMIT finished(outcomes.value());
        else
          Q_EMIT failed(QString::fromStdString(outcomes.error()));
      });
}

}  // namespace relief::ui::inline tasks
