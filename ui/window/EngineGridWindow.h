// EngineGridWindow: View > Engine Grid. The viewport's view of the material drawn by Relief's
// exact trace and by each engine preview side by side, each with its mean UV error against the
// exact trace (renderer/EngineGrid.h), so an artist sees before exporting what each engine will
// make of the relief. The GL passes run offscreen on the GUI thread (about a second); the exact
// traces run in the background, the window saying so meanwhile. Refresh draws the current
// view again; the picture can be saved.
#pragma once

#include "core/image/Image.h"
#include "ui/Forward.h"

#include <QDialog>

class QLabel;
class QPushButton;

namespace relief::ui::inline window {

class EngineGridWindow : public QDialog {
  Q_OBJECT

 public:
  EngineGridWindow(ViewDocument* view, ViewportWidget* viewport, QWidget* parent = nullptr);
  ~EngineGridWindow() override;

  // Renders the viewport's current view and starts the traces.
  void refresh();
  // Blocks until the traces have finished (tests).
  void waitForGrid();
  const core::Image& picture() const { return m_picture; }
  const QString& summary() const { return m_summary; }

 Q_SIGNALS:
  void gridReady();

 private:
  void saveImage();

  ViewDocument* m_view;
  ViewportWidget* m_viewport;
  BackgroundTask* m_task;
  QLabel* m_pictureLabel;
  QLabel* m_summaryLabel;
  QPushButton* m_save;
  core::Image m_picture;
  QString m_summary;
};

}  // namespace relief::ui::inline window
