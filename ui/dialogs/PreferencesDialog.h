// PreferencesDialog: autosave interval, what to open on start, the mesh for new documents.
// Reads and writes AppSettings; the caller applies what changed.
#pragma once

#include <QDialog>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace relief::ui::inline dialogs {

class PreferencesDialog : public QDialog {
  Q_OBJECT

 public:
  explicit PreferencesDialog(QWidget* parent = nullptr);

  QSpinBox* autosaveBox() const { return m_autosave; }
  QCheckBox* nativeCompressedBox() const { return m_nativeCompressed; }
  // Stores the choices (called on OK).
  void store();

 private:
  QSpinBox* m_autosave;
  QCheckBox* m_openSample;
  QComboBox* m_defaultMesh;
  QCheckBox* m_nativeCompressed;
};

}  // namespace relief::ui::inline dialogs
