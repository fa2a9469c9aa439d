// MainWindow: the editor. The viewport in the centre, docks for maps, parameters, light,
// generators, presets and the undo history, menus with shortcuts, drag-and-drop of maps and
// presets, and a status bar with the frame time. It owns the document; the file workflow
// (open, save, recovery) is DocumentFiles'. Window layout is kept across runs.
#pragma once

#include "core/material/MapSlot.h"
#include "core/preset/MaterialPreset.h"
#include "ui/Forward.h"

#include <QMainWindow>
#include <QStringList>

#include <optional>

class QAction;
class QComboBox;
class QLabel;

namespace relief::ui::inline window {

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  MaterialDocument* document() const { return m_document; }
  ViewDocument* viewDocument() const { return m_view; }
  ViewportWidget* viewport() const { return m_viewport; }
  ParameterPanel* parameterPanel() const { return m_parameters; }
  LightPanel* lightPanel() const { return m_light; }
  GeneratePanel* generatePanel() const { return m_generate; }
  CompressPanel* compressPanel() const { return m_compressPanel; }
  // How the compressed previews reach the GPU ("... uploaded natively"), shown in the status bar.
  QLabel* compressedUploadLabel() const;
  QComboBox* debugViewBox() const;
  QComboBox* meshBox() const;
  QAction* compareAction() const;
  DocumentFiles* files() const { return m_files; }
  PresetLibrary* presetLibrary() const { return m_library; }
  // The mesh shown: a primitive's name or a mesh file's path (as a preset stores it).
  const QString& meshSource() const;

  // Opens a preset (asking first if there are unsaved changes); reports problems in dialogs.
  bool openPreset(const QString& path);
  // Where the bundled presets are: listed in the library, never overwritten by Save.
  void setBundledPresetFolder(const QString& folder);
  // Renders the viewport's current frame offscreen at any size and saves it (PNG, JPEG, TIFF).
  bool saveViewportImage(const QString& path, int width, int height);
  // Shows the main shortcuts; also Help > Keyboard Shortcuts.
  void showShortcuts();
  // Loads an image into a slot: the given one, else the one its name hints at, else the one
  // the user picks. Returns false (after telling the user) when the file cannot be used.
  bool loadMapFile(const QString& path, std::optional<core::MapSlot> slot = std::nullopt);
  // A primitive by name (plane, cube, ...) or a mesh file (Assimp); problems in a dialog.
  bool showMesh(const QString& nameOrPath);
  // What a drop does: presets are opened, images assigned to slots.
  void openFiles(const QStringList& paths);

  static bool isImageFile(const QString& path);
  static bool isPresetFile(const QString& path);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createDocks();
  void createMenus();
  void chooseMesh();
  void updateTitle();
  void showControlsHelp();
  void showExportDialog();
  void showPreferences();
  void restoreWindowState();
  void saveWindowState();

  MaterialDocument* m_document;
  ViewDocument* m_view;
  ViewportWidget* m_viewport;
  CostTableWindow* m_costTable = nullptr;
  ParameterPanel* m_parameters = nullptr;
  MapsPanel* m_maps = nullptr;
  LightPanel* m_light = nullptr;
  GeneratePanel* m_generate = nullptr;
  CompressPanel* m_compressPanel = nullptr;
  ViewToolBar* m_toolBar = nullptr;
  ViewportStatus* m_status = nullptr;
  DocumentFiles* m_files = nullptr;
  PresetLibrary* m_library = nullptr;
  MapFileLoader* m_mapLoader = nullptr;
  ViewportImageExport* m_imageExport = nullptr;
};

}  // namespace relief::ui::inline window
