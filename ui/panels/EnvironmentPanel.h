// EnvironmentPanel: pbr shading's image-based light and the background, in the Light dock: the
// environment (a built-in, or an EXR/HDR file or BC6H texture read off the GUI thread and
// checked before it is shown), its intensity and rotation, what the background shows, and
// "Save as BC6H…": the environment compressed as it would ship, then lighting the material.
#pragma once

#include "ui/Forward.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace relief::ui::inline panels {

class EnvironmentPanel : public QWidget {
  Q_OBJECT

 public:
  explicit EnvironmentPanel(ViewDocument* view, QWidget* parent = nullptr);
  ~EnvironmentPanel() override;

  QComboBox* sourceBox() const { return m_source; }
  QDoubleSpinBox* intensityBox() const { return m_intensity; }
  ParameterSlider* rotationControl() const { return m_rotation; }
  QComboBox* backgroundBox() const { return m_background; }
  QPushButton* saveCompressedButton() const { return m_saveCompressed; }
  QLabel* compressedNote() const { return m_compressedNote; }

  // Reads `path` off the GUI thread and shows it when it is a usable environment; otherwise
  // says why in a message box naming the file. The file dialog's choice ends here too.
  void loadFile(const QString& path);
  // Compresses the environment shown into BC6H at `path` (.ktx2, supercompressed with
  // Zstandard 19, or .dds; with mipmaps) off the GUI thread, then lights the material with the
  // saved file as one undo step and says what it weighs and how far it is from the original.
  // The button's file dialog ends here.
  void saveCompressed(const QString& path);

 Q_SIGNALS:
  // A file finished loading: shown (ok) or refused (message names the file). For tests.
  void fileLoaded(bool ok, const QString& message);
  // saveCompressed finished: saved and shown (ok), or why not.
  void compressedSaved(bool ok, const QString& message);

 public Q_SLOTS:
  void showEnvironment();  // reads the view document's environment into the controls

 private:
  // The controls' intensity, rotation and background as an edit of the view document; a
  // rotation drag merges into one undo step.
  void applyEnvironment(bool dragging = false);
  void sourceChosen(int index);
  void chooseFile();
  void chooseCompressedPath();
  // The combo's item for a file, added once (after the built-ins, before "File…").
  int fileItem(const QString& path);

  ViewDocument* m_view;
  int m_dragEdit = 0;  // the view document's interactive edit of a rotation drag
  BackgroundTask* m_loader;
  QComboBox* m_source;
  QDoubleSpinBox* m_intensity;
  ParameterSlider* m_rotation;
  QComboBox* m_background;
  QPushButton* m_saveCompressed;
  QLabel* m_compressedNote;
  int m_shownIndex = 0;  // the source item shown, to go back to when a file is refused
};

}  // namespace relief::ui::inline panels
