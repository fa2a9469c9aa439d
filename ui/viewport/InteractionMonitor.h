// InteractionMonitor: whether the user is in the middle of a continuous gesture anywhere in the
// application: a mouse button held (dragging a slider, the camera, the light, the divider) or a
// wheel turned a moment ago. It watches the application's events rather than asking
// QGuiApplication::mouseButtons(), which only follows events that came through a window (not
// those sent to a widget directly, as accessibility tools and tests do).
#pragma once

#include <QElapsedTimer>
#include <QObject>

namespace relief::ui::inline viewport {

class InteractionMonitor : public QObject {
  Q_OBJECT

 public:
  // A wheel gesture counts as going on for this long after its last step.
  static constexpr int kWheelGestureMs = 300;

  explicit InteractionMonitor(QObject* parent = nullptr);  // watches the running application
  bool isInteracting() const;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  Qt::MouseButtons m_held;
  QElapsedTimer m_sinceWheel;  // invalid until the first wheel event
};

}  // namespace relief::ui::inline viewport
