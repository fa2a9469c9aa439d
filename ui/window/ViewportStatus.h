// ViewportStatus: what the viewport reports, in the main window's status bar: the error view's
// progress, the cone map being built, an environment that cannot be read, the frame time (and
// the resolution of reduced frames), the height samples per pixel, how compressed maps reach the
// GPU, and the GPU's name. Messages about the material that was open go when another opens.
#pragma once

#include "ui/Forward.h"

#include <QObject>

class QLabel;
class QProgressBar;
class QStatusBar;

namespace relief::ui::inline window {

class ViewportStatus : public QObject {
  Q_OBJECT

 public:
  ViewportStatus(ViewportWidget* viewport, MaterialDocument* document, QStatusBar* bar);

  QLabel* compressedUploadLabel() const { return m_compressedLabel; }

 private:
  void showFrameTime(double milliseconds, double scale);

  QStatusBar* m_bar;
  QProgressBar* m_progress;
  QLabel* m_compressedLabel;
  QLabel* m_rendererLabel;
  QLabel* m_samples;  // height samples per pixel (ViewportWidget::samplesMeasured)
  QLabel* m_frameTime;
};

}  // namespace relief::ui::inline window
