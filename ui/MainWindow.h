// MainWindow: the editor. The viewport in the centre, docks for maps, parameters and the undo
// history, menus with shortcuts, drag-and-drop of maps and presets, and a status bar with the
// frame time. It owns the document; it is the only place that shows dialogs.
#pragma once

#include "core/MapSlot.h"

#include <QMainWindow>
#include <QStringList>

#include <optional>

class QAction;
class QComboBox;
class QLabel;
class QProgressBar;

namespace relief::ui {

class GeneratePanel;
class LightPanel;
class MapsPanel;
class MaterialDocument;
class ParameterPanel;
class ViewportWidget;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  MaterialDocument* document() const { return m_document; }
  ViewportWidget* viewport() const { return m_viewport; }
  ParameterPanel* parameterPanel() const { return m_parameters; }
  LightPanel* lightPanel() const { return m_light; }
  GeneratePanel* generatePanel() const { return m_generate; }
  QComboBox* debugViewBox() const { return m_debugView; }
  QComboBox* meshBox() const { return m_meshBox; }
  QAction* compareAction() const { return m_compare; }

  // Opens a preset; reports problems in a dialog (errors) or the status bar (warnings).
  bool openPreset(const QString& path);
  // Loads an image into a slot: the given one, else the one its name hints at, else the one
  // the user picks. Returns false (after telling the user) when the file cannot be used.
  bool loadMapFile(const QString& path, std::optional<core::MapSlot> slot = std::nullopt);
  // Opens a mesh through Assimp; reports problems in a dialog.
  bool openMesh(const QString& path);
  // What a drop does: presets are opened, images assigned to slots.
  void openFiles(const QStringList& paths);

  static bool isImageFile(const QString& path);
  static bool isPresetFile(const QString& path);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createDocks();
  void createMenus();
  void createToolBar();
  void chooseMesh();
  void showFrameTime(double milliseconds);
  void updateTitle();
  void chooseMapFile(std::optional<core::MapSlot> slot);
  void choosePreset();
  void showControlsHelp();

  MaterialDocument* m_document;
  ViewportWidget* m_viewport;
  ParameterPanel* m_parameters = nullptr;
  MapsPanel* m_maps = nullptr;
  LightPanel* m_light = nullptr;
  GeneratePanel* m_generate = nullptr;
  QComboBox* m_debugView = nullptr;
  QComboBox* m_meshBox = nullptr;
  QAction* m_compare = nullptr;
  QProgressBar* m_progress;
  QLabel* m_frameTime;
  QLabel* m_rendererLabel;
  QString m_lastFolder;
};

}  // namespace relief::ui
