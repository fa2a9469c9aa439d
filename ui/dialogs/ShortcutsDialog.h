// ShortcutsDialog: Help > Keyboard Shortcuts. Lists every menu action that has a shortcut,
// read from the menu bar itself so the list cannot fall behind, and the viewport's mouse and
// key controls.
#pragma once

#include <QDialog>

class QMenuBar;

namespace relief::ui::inline dialogs {

class ShortcutsDialog : public QDialog {
  Q_OBJECT

 public:
  ShortcutsDialog(const QMenuBar* menuBar, const QString& viewportControls,
                  QWidget* parent = nullptr);
};

}  // namespace relief::ui::inline dialogs
