// GeneratorRunner; see GeneratorRunner.h.
#include "ui/tasks/GeneratorRunner.h"

#include "core/generators/ImageFilters.h"

#include <algorithm>
#include <cmath>

namespace relief::ui::inline tasks {

struct GeneratorRunner::Job {
  core::GeneratorKind kind;
  std::vector<std::shared_ptr<const core::Image>> inputs;
  core::GeneratorValues values;
};

namespace {

using Outcome = core::Result<core::GeneratedMap>;

}  // namespace

GeneratorRunner::GeneratorRunner(QObject* parent) : QObject(parent) {
  connect(&m_task, &BackgroundTask::progress, this, [this](double fraction) {
    if (m_fullSize)
      Q_EMIT progress(fraction);
  });
}

void GeneratorRunner::request(core::GeneratorKind kind,
                              std::vector<std::shared_ptr<const core::Image>> inputs,
                              core::GeneratorValues values) {
  auto job = std::make_shared<const Job>(Job{kind, std::move(inputs), std::move(values)});
  m_fullSize = false;
  m_task.run<Outcome>(
      [job](const core::WorkControl& control) -> Outcome {
        // The previews of the inputs, at most kPreviewSize on their longer side; optional
        // inputs not given stay null.
        const auto given = std::find_if(job->inputs.begin(), job->inputs.end(),
                                        [](const auto& input) { return bool(input); });
        if (given == job->inputs.end())
          return core::Error{"no input maps"};
        const core::Image& first = **given;
        const double scale =
            std::min(1.0, double(kPreviewSize) / std::max(first.width(), first.height()));
        std::vector<core::Image> small;
        std::vector<const core::Image*> pointers;
        small.reserve(job->inputs.size());
        for (const auto& input : job->inputs) {
          if (!input) {
            pointers.push_back(nullptr);
          } else if (scale < 1.0) {
            small.push_back(
                core::resizeImage(*input, std::max(1, int(std::lround(input->width() * scale))),
                                  std::max(1, int(std::lround(input->height() * scale)))));
            pointers.push_back(&small.back());
          } else {
            pointers.push_back(input.get());
          }
        }
        core::WorkControl quiet;  // the preview's progress is not shown
        quiet.cancel = control.cancel;
        return core::runGenerator({job->kind, pointers, job->values, scale}, quiet);
      },
      [this, job](Outcome&& preview) {
        if (preview.ok())
          Q_EMIT previewReady(preview.value());
        startFullSize(job);
      });
}

void GeneratorRunner::startFullSize(std::shared_ptr<const Job> job) {
  m_fullSize = true;
  m_task.run<Outcome>(
      [job](const core::WorkControl& control) -> Outcome {
        std::vector<const core::Image*> pointers;
        for (const auto& input : job->inputs)
          pointers.push_back(input.get());
        return core::runGenerator({job->kind, pointers, job->values, 1.0}, control);
      },
      [this](Outcome&& result) {
        if (result.ok()) {
          Q_EMIT resultReady(result.value());
        } else if (result.error() != "cancelled") {
          Q_EMIT failed(QString::fromStdString(result.error()));
        }
      });
}

}  // namespace relief::ui::inline tasks
