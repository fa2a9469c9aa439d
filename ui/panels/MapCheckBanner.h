// MapCheckBanner: the Maps dock's warning when the normal and height maps disagree with each
// other or with how the material reads them (core/generators/MapCheck.h): a normal map that is
// DirectX while the material reads OpenGL, a height map that stores depth, or two maps of
// different surfaces. It re-checks in the background whenever either map or the parameters
// that say how they are read change, and offers the fix as one click: an undoable parameter
// change, never an edit of the map itself.
#pragma once

#include "core/generators/MapCheck.h"
#include "ui/Forward.h"

#include <QFrame>

class QLabel;
class QPushButton;

namespace relief::ui::inline panels {

class MapCheckBanner : public QFrame {
  Q_OBJECT

 public:
  explicit MapCheckBanner(MaterialDocument* document, QWidget* parent = nullptr);

  // Blocks until the check in flight (if any) has been shown (tests).
  void waitForCheck();

 private:
  void recheck();
  void showResult(const core::MapCheckResult& result);

  MaterialDocument* m_document;
  BackgroundTask* m_task;
  QLabel* m_text;
  QPushButton* m_flipY;
  QPushButton* m_invertHeight;
};

}  // namespace relief::ui::inline panels
