// InteractionMonitor; see InteractionMonitor.h.
#include "ui/viewport/InteractionMonitor.h"

#include <QCoreApplication>
#include <QMouseEvent>

namespace relief::ui::inline viewport {

InteractionMonitor::InteractionMonitor(QObject* parent) : QObject(parent) {
  if (QCoreApplication* application = QCoreApplication::instance())
    application->installEventFilter(this);
}

bool InteractionMonitor::isInteracting() const {
  return m_held != Qt::NoButton ||
         (m_sinceWheel.isValid() && m_sinceWheel.elapsed() < kWheelGestureMs);
}

bool InteractionMonitor::eventFilter(QObject* watched, QEvent* event) {
  switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
      // The buttons still down after the event: the same event reaching the window and then
      // the widget (and its parents) sets the same state.
      m_held = static_cast<QMouseEvent*>(event)->buttons();
      break;
    case QEvent::Wheel:
      m_sinceWheel.start();
      break;
    case QEvent::ApplicationDeactivate:
      // A release outside the application (a window manager grab) is never delivered.
      m_held = Qt::NoButton;
      break;
    default:
      break;
  }
  return QObject::eventFilter(watched, event);
}

}  // namespace relief::ui::inline viewport
