// PresetLibrary: the bundled presets (samples/) and the user's own (AppDataLocation/presets)
// as a grid of thumbnails, each rendered offscreen by the renderer on a sphere and cached on
// disk. Double-click (or Open) opens a preset whole; Apply takes its technique and parameters
// onto the current maps as one undo step; Save current… adds the current material (with
// copies of its maps, so the library does not depend on where they were).
#pragma once

#include "ui/Forward.h"

#include <QIcon>
#include <QStringList>
#include <QWidget>

#include <memory>

class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace relief::renderer {
class OffscreenRenderer;
}

namespace relief::core::inline material {
class Material;
}
namespace relief::core::inline preset {
struct LoadedPreset;
struct Preset;
}  // namespace relief::core::inline preset

namespace relief::ui::inline document {

class PresetLibrary : public QWidget {
  Q_OBJECT

 public:
  static constexpr int kThumbnailSize = 112;

  explicit PresetLibrary(MaterialDocument* document, QWidget* parent = nullptr);
  ~PresetLibrary() override;

  // Where Save current… puts presets: AppDataLocation/presets.
  static QString userFolder();
  // The bundled presets' folder (each preset in a subfolder, as samples/ is laid out).
  void setBundledFolder(const QString& folder);
  // Lists the presets again (after a save or a delete); thumbnails come as they are ready.
  void refresh();

  QListWidget* list() const { return m_list; }
  // The path of the selected preset, or empty.
  QString selectedPath() const;
  // Takes the preset's technique and parameters (not its maps) as one undo step.
  bool applyParameters(const QString& path);
  bool deletePreset(const QString& path);
  // Save current…: asks for a name (and before replacing one), then writes the preset as a
  // package in the background (the library keeps its own copies of the maps, so it does not
  // break when the originals move) and lists it when it is written.
  void saveCurrent(core::Preset preset);
  bool isSaving() const;

 Q_SIGNALS:
  void openRequested(const QString& path);
  void saveCurrentRequested();
  void statusMessage(const QString& message, int timeoutMs);

 private:
  void addPresets(const QString& folder, bool user);
  void loadNextThumbnail();
  void renderThumbnail(const QString& source, const core::Material& material);
  QIcon cachedThumbnail(const QString& path) const;
  QString thumbnailCachePath(const QString& path) const;
  void updateButtons();

  MaterialDocument* m_document;
  BackgroundTask* m_saving;
  BackgroundTask* m_loading;  // thumbnails: the next preset's maps
  QListWidget* m_list;
  QPushButton* m_open;
  QPushButton* m_apply;
  QPushButton* m_delete;
  QString m_bundledFolder;
  QStringList m_pendingThumbnails;
  std::unique_ptr<renderer::OffscreenRenderer> m_renderer;
  bool m_rendererFailed = false;
};

}  // namespace relief::ui::inline document
