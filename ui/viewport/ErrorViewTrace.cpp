// ErrorViewTrace; see ErrorViewTrace.h.
#include "ui/viewport/ErrorViewTrace.h"

#include "renderer/ErrorView.h"
#include "renderer/ImageConversion.h"
#include "renderer/MaterialRenderer.h"
#include "ui/tasks/BackgroundTask.h"

#include <algorithm>
#include <memory>

namespace relief::ui::inline viewport {

ErrorViewTrace::ErrorViewTrace(QObject* parent)
    : QObject(parent), m_task(new BackgroundTask(this)) {
  connect(m_task, &BackgroundTask::progress, this,
          [this](double fraction) { Q_EMIT progress(int(fraction * 1000.0), 1000); });
  connect(m_task, &BackgroundTask::cancelled, this, [this] { Q_EMIT progress(0, 0); });
}

ErrorViewTrace::~ErrorViewTrace() {
  m_task->cancel();
  m_task->waitForFinished();
}

void ErrorViewTrace::clear() {
  m_map.reset();
  m_image = {};
}

core::Status ErrorViewTrace::start(renderer::MaterialRenderer& renderer,
                                   const renderer::FrameSettings& frame, int pixelWidth,
                                   int pixelHeight) {
  m_task->cancel();
  clear();
  auto inputs = renderer::renderErrorViewInputs(renderer, frame, pixelWidth, pixelHeight);
  if (!inputs)
    return core::makeError(inputs.error());
  m_task->run<core::UvErrorMap>(
      [inputs = std::make_shared<renderer::ErrorViewInputs>(std::move(inputs).value())](
          const core::WorkControl& control) {
        return core::computeUvErrorMap(
            inputs->finalUv, inputs->eyeRays, inputs->field,
            [&control](int done, int total) {
              if (done % 16 == 0)
                control.report(double(done) / double(std::max(total, 1)));
            },
            control.cancel);
      },
      [this](core::UvErrorMap&& map) {
        m_map = std::move(map);
        m_image =
            renderer::toDisplayImage(core::colorizeErrorMap(*m_map, core::kErrorDisplayTexels));
        Q_EMIT progress(0, 0);
        Q_EMIT finished(QString::fromStdString(core::describeUvError(*m_map)));
      });
  return {};
}

}  // namespace relief::ui::inline viewport
