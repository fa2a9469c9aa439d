// MaterialDocument: the material being edited, its file and its undo history. Widgets change
// the material only through the document's methods, which push undo commands; views listen
// to the signals and update only what changed.
#pragma once

#include "core/Material.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <memory>
#include <utility>
#include <vector>

namespace relief::ui {

class MaterialDocument : public QObject {
  Q_OBJECT

 public:
  explicit MaterialDocument(QObject* parent = nullptr);

  const core::Material& material() const { return m_material; }
  QUndoStack* undoStack() { return &m_undoStack; }
  const QString& filePath() const { return m_filePath; }

  // Replaces the whole material (a preset was opened); the undo history starts afresh.
  void reset(core::Material material, const QString& filePath);

  // Starts an interactive edit (a slider drag). Every setParameter() call with the returned
  // id and the same parameter merges into one undo step.
  int beginInteractiveEdit() { return ++m_lastInteractiveEdit; }
  void setParameter(core::ParamId id, double value, int interactiveEdit = 0);
  void resetParameters();
  void setTechnique(core::Technique technique);
  void setMap(core::MapSlot slot, std::shared_ptr<const core::Image> image,
              const QString& sourcePath);
  void clearMap(core::MapSlot slot);
  // A generated map and the parameter changes that go with it, as one undo step.
  void applyGenerated(core::MapSlot slot, std::shared_ptr<const core::Image> image,
                      const QString& label,
                      const std::vector<std::pair<core::ParamId, double>>& parameterChanges);

  // Used by the undo commands: change the material and notify, without pushing anything.
  void applyParameter(core::ParamId id, double value);
  void applyParameters(const core::ParameterValues& values);
  void applyTechnique(core::Technique technique);
  void applyMap(core::MapSlot slot, const core::MaterialMap& map);

 Q_SIGNALS:
  void parameterChanged(relief::core::ParamId id);
  void techniqueChanged();
  void mapChanged(relief::core::MapSlot slot);
  void materialReset();

 private:
  core::Material m_material;
  QUndoStack m_undoStack;
  QString m_filePath;
  int m_lastInteractiveEdit = 0;
};

}  // namespace relief::ui
