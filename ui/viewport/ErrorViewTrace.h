// ErrorViewTrace: the viewport's UV error view. Every pixel's exact intersection is traced on the
// CPU in the background (seconds), and its UV error against what the frame drew is kept as
// numbers and as a heat map to paint over the frame. A new trace drops the one running.
#pragma once

#include "core/base/Result.h"
#include "core/tracing/UvErrorMap.h"
#include "ui/Forward.h"

#include <QImage>
#include <QObject>

#include <optional>

namespace relief::renderer {
class MaterialRenderer;
struct FrameSettings;
}  // namespace relief::renderer

namespace relief::ui::inline viewport {

class ErrorViewTrace : public QObject {
  Q_OBJECT

 public:
  explicit ErrorViewTrace(QObject* parent = nullptr);
  ~ErrorViewTrace() override;

  // Renders what the trace needs for `frame` at this size (with the GL context current) and
  // starts it; the error when that cannot be rendered.
  core::Status start(renderer::MaterialRenderer& renderer, const renderer::FrameSettings& frame,
                     int pixelWidth, int pixelHeight);
  void clear();  // the numbers and the heat map (a trace running goes on)

  const std::optional<core::UvErrorMap>& map() const { return m_map; }
  const QImage& image() const { return m_image; }

 Q_SIGNALS:
  void progress(int done, int total);     // total 0: finished or cancelled
  void finished(const QString& summary);  // core::describeUvError's

 private:
  BackgroundTask* m_task;
  std::optional<core::UvErrorMap> m_map;
  QImage m_image;
};

}  // namespace relief::ui::inline viewport
