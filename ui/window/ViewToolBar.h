// ViewToolBar: the main window's "View" toolbar — what the viewport shows (the shaded material
// or a diagnostic view), the mesh it is shown on, the tile preview, the view distance, the engine
// preview (and the engine grid window) and the A|B comparison. The debug view and the mesh are the
// view document's, and the boxes follow it whoever changed them (a preset, undo); the comparison is
// the viewport's own.
#pragma once

#include "ui/Forward.h"

#include <QString>
#include <QToolBar>

class QAction;
class QComboBox;

namespace relief::ui::inline window {

class ViewToolBar : public QToolBar {
  Q_OBJECT

 public:
  ViewToolBar(ViewDocument* view, ViewportWidget* viewport, QWidget* parent = nullptr);

  QComboBox* debugViewBox() const { return m_debugView; }
  QComboBox* meshBox() const { return m_meshBox; }
  QAction* compareAction() const { return m_compare; }
  QAction* holdAction() const { return m_holdAsB; }
  QAction* tileAction() const { return m_tile; }
  QAction* seamsAction() const { return m_seams; }
  QAction* hexAction() const { return m_hex; }
  QComboBox* distanceBox() const { return m_distanceBox; }
  QAction* fartherAction() const { return m_farther; }  // ]: the next distance
  QAction* closerAction() const { return m_closer; }    // [: the previous one
  QComboBox* engineBox() const { return m_engineBox; }
  QAction* engineGridAction() const { return m_engineGrid; }
  QAction* engineCycleAction() const { return m_engineCycle; }  // E: Relief, then each engine
  // The engine grid window, once opened (null before).
  EngineGridWindow* engineGridWindow() const { return m_engineGridWindow; }

 Q_SIGNALS:
  // A primitive was picked in the mesh box (by name); the window loads it and reports problems.
  void meshRequested(const QString& name);

 private:
  void createDistanceControls();
  void showMeshSource(const QString& source);

  ViewDocument* m_view;
  ViewportWidget* m_viewport;
  QComboBox* m_debugView;
  QComboBox* m_meshBox;
  QAction* m_compare;
  QAction* m_holdAsB;
  QAction* m_tile;
  QAction* m_seams;
  QAction* m_hex;
  QComboBox* m_distanceBox = nullptr;
  QAction* m_farther = nullptr;
  QAction* m_closer = nullptr;
  QComboBox* m_engineBox;
  QAction* m_engineGrid;
  QAction* m_engineCycle;
  EngineGridWindow* m_engineGridWindow = nullptr;
};

}  // namespace relief::ui::inline window
