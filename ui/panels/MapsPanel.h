// MapsPanel: one row per map slot with a thumbnail, the file name and size, and buttons to
// load or clear the map. Loading is delegated to the main window (it owns file dialogs and
// error reporting); the panel only shows the document's state.
#pragma once

#include "core/material/MapSlot.h"
#include "ui/Forward.h"

#include <QWidget>

#include <array>

class QLabel;

namespace relief::ui::inline panels {

class MapsPanel : public QWidget {
  Q_OBJECT

 public:
  explicit MapsPanel(MaterialDocument* document, QWidget* parent = nullptr);

  static constexpr int kThumbnailSize = 72;

 Q_SIGNALS:
  void loadRequested(relief::core::MapSlot slot);
  void loadOrmRequested();

 private:
  void showSlot(core::MapSlot slot);
  void showAll();

  struct Row {
    QLabel* thumbnail = nullptr;
    QLabel* description = nullptr;
  };

  MaterialDocument* m_document;
  std::array<Row, core::kMapSlotCount> m_rows;
};

}  // namespace relief::ui::inline panels
