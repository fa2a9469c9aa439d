// TileableBar: the Maps dock's "Make tileable" row. It makes every map the material holds
// tile, with one cut for all of them (core/generators/Tileable.h), in the background with
// progress, and puts the result in as one undo step; it says how strong the seams were and are.
// The viewport's Tile 3×3 and Seams (the View toolbar) are where the artist judges the result.
#pragma once

#include "ui/Forward.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace relief::ui::inline panels {

class TileableBar : public QWidget {
  Q_OBJECT

 public:
  explicit TileableBar(MaterialDocument* document, QWidget* parent = nullptr);

  // Blocks until the run in flight (if any) has been applied (tests).
  void waitForRun();

 private:
  void makeTileable();
  void showMaps();

  MaterialDocument* m_document;
  BackgroundTask* m_task;
  QComboBox* m_method;
  QPushButton* m_run;
  QProgressBar* m_progress;
  QLabel* m_report;
};

}  // namespace relief::ui::inline panels
