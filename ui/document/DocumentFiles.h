// DocumentFiles: the file side of the editor. New, Open, Save, Save As, Revert, recent files,
// the prompt before unsaved changes would be lost, and autosave with recovery after a crash.
// It asks the window for the view to store in a preset (camera, light, mesh) and gives it
// the view of a preset that was opened.
#pragma once

#include "core/preset/MaterialPreset.h"
#include "ui/Forward.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>

class QMenu;
class QWidget;

namespace relief::ui::inline document {

class DocumentFiles : public QObject {
  Q_OBJECT

 public:
  // `view` holds a preset's view (mesh, camera, light, environment, display): shown when a
  // preset is opened, read back when it is saved.
  DocumentFiles(MaterialDocument* document, ViewDocument* view, QWidget* dialogParent);
  ~DocumentFiles() override;

  // Presets in this folder (the bundled samples) are not overwritten: Save asks for a name.
  void setProtectedFolder(const QString& folder) { m_protectedFolder = folder; }

  // Each returns whether it happened (false: cancelled or failed, after telling the user).
  bool newDocument();
  bool open(const QString& path);
  bool openWithPrompt();  // File > Open's dialog
  bool save();
  bool saveAs();
  bool revert();
  // Before unsaved changes would be lost: asks Save / Discard / Cancel. True: go ahead.
  bool maybeSave(const QString& reason);

  // Keeps `menu` listing the recent files (rebuilt whenever it is shown).
  void attachRecentMenu(QMenu* menu);
  // Offers the work of sessions that crashed; recovers the one the user picks.
  void offerRecovery();
  // Applies the autosave preference (minutes; 0 is off).
  void updateAutosaveInterval();
  RecoveryStore* recovery() const { return m_recovery; }
  // Writes the recovery file now if there are unsaved changes (the timer calls this).
  void autosaveNow();

  // The name the title shows: the file's, else the material's, else "untitled".
  QString displayName() const;

 Q_SIGNALS:
  void statusMessage(const QString& message, int timeoutMs);

 private:
  bool openFile(const QString& path);  // no unsaved-changes prompt
  bool isProtected(const QString& path) const;
  bool saveTo(const QString& path);

  MaterialDocument* m_document;
  QWidget* m_parent;
  ViewDocument* m_view;
  void showView(const core::ViewState& view);
  QString m_protectedFolder;
  RecoveryStore* m_recovery;
  QTimer m_autosaveTimer;
};

}  // namespace relief::ui::inline document
