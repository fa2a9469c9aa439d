// MaterialDocument: the material being edited, its file and its undo history. Widgets change
// the material only through the document's methods, which push undo commands; views listen
// to the signals and update only what changed.
#pragma once

#include "core/material/Material.h"
#include "core/preset/MaterialPreset.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <memory>
#include <utility>
#include <vector>

namespace relief::ui::inline document {

class MaterialDocument : public QObject {
  Q_OBJECT

 public:
  explicit MaterialDocument(QObject* parent = nullptr);

  const core::Material& material() const { return m_material; }
  QUndoStack* undoStack() { return &m_undoStack; }
  // The preset file this document was opened from or saved to; empty for a new one.
  const QString& filePath() const { return m_filePath; }
  // Unsaved edits: the undo stack is not at the state last opened or saved.
  bool isModified() const { return !m_undoStack.isClean(); }

  // Replaces the whole material (a preset was opened); the undo history starts afresh.
  void reset(core::Material material, const QString& filePath);
  // Replaces everything with a loaded preset: the material, its compression choices and the
  // keys this program does not know (kept for the next save). The view is the window's.
  void reset(core::Preset preset, const QString& filePath);
  // The document as a preset, with the given view (camera, light, mesh).
  core::Preset toPreset(const core::ViewState& view) const;
  // Saves atomically to `path`; on success the document takes the path, becomes unmodified,
  // and maps that had no file point at the files the save wrote (not an undoable edit).
  core::Result<core::SavedPreset> save(const QString& path, const core::ViewState& view);

  // Starts an interactive edit (a slider drag). Every setParameter() call with the returned
  // id and the same parameter merges into one undo step.
  int beginInteractiveEdit() { return ++m_lastInteractiveEdit; }
  void setParameter(core::ParamId id, double value, int interactiveEdit = 0);
  void resetParameters();
  void setTechnique(core::Technique technique);
  // `sourceChannel`: the file's channel the map is (an ORM texture's), -1 for the whole file.
  void setMap(core::MapSlot slot, std::shared_ptr<const core::Image> image,
              const QString& sourcePath, int sourceChannel = -1);
  void clearMap(core::MapSlot slot);
  // The compression chosen for a slot (saved with the preset); one undo step per change.
  const core::MapCompression& compression(core::MapSlot slot) const {
    return m_compression[std::size_t(slot)];
  }
  void setCompression(core::MapSlot slot, const core::MapCompression& compression);
  // Another material's technique and parameters (not its maps), as one undo step.
  void applyLook(const core::Material& from, const QString& label);
  // A generated map and the parameter changes that go with it, as one undo step.
  void applyGenerated(core::MapSlot slot, std::shared_ptr<const core::Image> image,
                      const QString& label,
                      const std::vector<std::pair<core::ParamId, double>>& parameterChanges);

  // Maps made together (a set made tileable), each replacing its slot's, as one undo step.
  void applyMaps(
      const std::vector<std::pair<core::MapSlot, std::shared_ptr<const core::Image>>>& maps,
      const QString& label);

  // Used by the undo commands: change the material and notify, without pushing anything.
  void applyParameter(core::ParamId id, double value);
  void applyParameters(const core::ParameterValues& values);
  void applyTechnique(core::Technique technique);
  void applyMap(core::MapSlot slot, const core::MaterialMap& map);
  void applyCompression(core::MapSlot slot, const core::MapCompression& compression);

 Q_SIGNALS:
  void parameterChanged(relief::core::ParamId id);
  void techniqueChanged();
  void mapChanged(relief::core::MapSlot slot);
  void materialReset();
  void compressionChanged(relief::core::MapSlot slot);
  void fileSaved();  // saved to filePath(); maps may now name the files the save wrote

 private:
  core::Material m_material;
  std::array<core::MapCompression, core::kMapSlotCount> m_compression;
  QJsonObject m_preserved;
  QUndoStack m_undoStack;
  QString m_filePath;
  int m_lastInteractiveEdit = 0;
};

}  // namespace relief::ui::inline document
