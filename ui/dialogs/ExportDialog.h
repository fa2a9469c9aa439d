// ExportDialog: File > Export. Chooses the kind (package, glTF 2.0, Godot 4 material; the list
// and texts are core's export table), the folder and, for a package, the map format and the
// compressed textures; runs the export in the background (BackgroundTask) with a progress
// indicator and Cancel, and reports what was written and what the target cannot represent.
#pragma once

#include "core/exporters/Exporter.h"
#include "core/mesh/Mesh.h"
#include "core/preset/MaterialPreset.h"
#include "ui/Forward.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace relief::ui::inline dialogs {

class ExportDialog : public QDialog {
  Q_OBJECT

 public:
  ExportDialog(core::Preset preset, core::Mesh mesh, QWidget* parent = nullptr);
  ~ExportDialog() override;

  QComboBox* kindBox() const { return m_kind; }
  QLineEdit* folderEdit() const { return m_folder; }
  QComboBox* mapFormatBox() const { return m_mapFormat; }
  QComboBox* texturesBox() const { return m_textures; }
  QPushButton* cancelButton() const { return m_cancel; }
  // What the last export wrote (its main file); empty before or after a failure.
  const QString& writtenPath() const { return m_writtenPath; }
  bool isExporting() const;

  // Starts the export with the dialog's choices; false when it cannot start (no folder).
  // `exportFinished` follows; on success the dialog reports what was written and accepts.
  bool startExport();

 Q_SIGNALS:
  void exportFinished(bool succeeded);

 private:
  void updateForKind();
  void restoreChoices();
  void saveChoices() const;
  void finishExport(core::Result<core::ExportResult>&& result, const QString& folder);
  core::ExportKind currentKind() const;

  core::Preset m_preset;
  core::Mesh m_mesh;
  QComboBox* m_kind;
  QLineEdit* m_folder;
  QComboBox* m_mapFormat;
  QComboBox* m_textures;
  QLabel* m_explanation;
  QProgressBar* m_progress;
  QPushButton* m_export = nullptr;
  QPushButton* m_cancel = nullptr;
  BackgroundTask* m_task;
  QString m_writtenPath;
};

}  // namespace relief::ui::dialogs
