// Undo commands for material edits. Each holds the old and the new value; a slider drag
// merges into one command (same parameter, same interactive-edit id).
#pragma once

#include "core/material/Material.h"
#include "core/preset/MaterialPreset.h"
#include "ui/Forward.h"

#include <QUndoCommand>

namespace relief::ui::inline document {

class SetParameterCommand : public QUndoCommand {
 public:
  SetParameterCommand(MaterialDocument* document, core::ParamId id, double oldValue,
                      double newValue, int interactiveEdit);
  void undo() override;
  void redo() override;
  int id() const override { return 1; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  MaterialDocument* m_document;
  core::ParamId m_parameter;
  double m_oldValue;
  double m_newValue;
  int m_interactiveEdit;  // 0: never merges
};

class SetAllParametersCommand : public QUndoCommand {
 public:
  SetAllParametersCommand(MaterialDocument* document, const core::ParameterValues& oldValues,
                          const core::ParameterValues& newValues);
  void undo() override;
  void redo() override;

 private:
  MaterialDocument* m_document;
  core::ParameterValues m_oldValues;
  core::ParameterValues m_newValues;
};

class SetTechniqueCommand : public QUndoCommand {
 public:
  SetTechniqueCommand(MaterialDocument* document, core::Technique oldTechnique,
                      core::Technique newTechnique);
  void undo() override;
  void redo() override;

 private:
  MaterialDocument* m_document;
  core::Technique m_oldTechnique;
  core::Technique m_newTechnique;
};

class SetCompressionCommand : public QUndoCommand {
 public:
  SetCompressionCommand(MaterialDocument* document, core::MapSlot slot,
                        core::MapCompression oldCompression, core::MapCompression newCompression);
  void undo() override;
  void redo() override;

 private:
  MaterialDocument* m_document;
  core::MapSlot m_slot;
  core::MapCompression m_old;
  core::MapCompression m_new;
};

class SetMapCommand : public QUndoCommand {
 public:
  SetMapCommand(MaterialDocument* document, core::MapSlot slot, core::MaterialMap oldMap,
                core::MaterialMap newMap);
  void undo() override;
  void redo() override;

 private:
  MaterialDocument* m_document;
  core::MapSlot m_slot;
  core::MaterialMap m_oldMap;
  core::MaterialMap m_newMap;
};

}  // namespace relief::ui::inline document
