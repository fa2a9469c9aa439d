// ExportDialog: File > Export. Chooses the kind (package, glTF 2.0, Godot 4 material), the
// folder and, for a package, the map format; runs the export in the background with a busy
// indicator and reports what was written and what the target cannot represent.
#pragma once

#include "core/material/MaterialPreset.h"
#include "core/mesh/Mesh.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;

namespace relief::ui::inline dialogs {

class ExportDialog : public QDialog {
  Q_OBJECT

 public:
  ExportDialog(core::Preset preset, core::Mesh mesh, QWidget* parent = nullptr);

  QComboBox* kindBox() const { return m_kind; }
  QLineEdit* folderEdit() const { return m_folder; }
  QComboBox* mapFormatBox() const { return m_mapFormat; }
  QComboBox* texturesBox() const { return m_textures; }
  // What the last export wrote (its main file) and any notes; empty before or after a failure.
  const QString& writtenPath() const { return m_writtenPath; }

  // Runs the export with the dialog's choices; true on success (the dialog then accepts).
  bool runExport();

 private:
  void updateForKind();

  core::Preset m_preset;
  core::Mesh m_mesh;
  QComboBox* m_kind;
  QLineEdit* m_folder;
  QComboBox* m_mapFormat;
  QComboBox* m_textures;
  QLabel* m_explanation;
  QString m_writtenPath;
};

}  // namespace relief::ui::inline dialogs
