// Undo commands; see MaterialCommands.h.
#include "ui/document/MaterialCommands.h"

#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"

#include <QFileInfo>

namespace relief::ui::inline document {
SetParameterCommand::SetParameterCommand(MaterialDocument* document, core::ParamId id,
                                         double oldValue, double newValue, int interactiveEdit)
    : m_document(document),
      m_parameter(id),
      m_oldValue(oldValue),
      m_newValue(newValue),
      m_interactiveEdit(interactiveEdit) {
  setText(QObject::tr("Change %1").arg(toQString(core::parameterSpec(id).label)));
}

void SetParameterCommand::undo() {
  m_document->applyParameter(m_parameter, m_oldValue);
}
void SetParameterCommand::redo() {
  m_document->applyParameter(m_parameter, m_newValue);
}

bool SetParameterCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = static_cast<const SetParameterCommand*>(other);
  if (m_interactiveEdit == 0 || next->m_interactiveEdit != m_interactiveEdit ||
      next->m_parameter != m_parameter) {
    return false;
  }
  m_newValue = next->m_newValue;
  return true;
}

SetAllParametersCommand::SetAllParametersCommand(MaterialDocument* document,
                                                 const core::ParameterValues& oldValues,
                                                 const core::ParameterValues& newValues)
    : m_document(document), m_oldValues(oldValues), m_newValues(newValues) {
  setText(QObject::tr("Reset parameters"));
}

void SetAllParametersCommand::undo() {
  m_document->applyParameters(m_oldValues);
}
void SetAllParametersCommand::redo() {
  m_document->applyParameters(m_newValues);
}

SetTechniqueCommand::SetTechniqueCommand(MaterialDocument* document, core::Technique oldTechnique,
                                         core::Technique newTechnique)
    : m_document(document), m_oldTechnique(oldTechnique), m_newTechnique(newTechnique) {
  setText(QObject::tr("Technique: %1").arg(toQString(core::techniqueLabel(newTechnique))));
}

void SetTechniqueCommand::undo() {
  m_document->applyTechnique(m_oldTechnique);
}
void SetTechniqueCommand::redo() {
  m_document->applyTechnique(m_newTechnique);
}

SetCompressionCommand::SetCompressionCommand(MaterialDocument* document, core::MapSlot slot,
                                             core::MapCompression oldCompression,
                                             core::MapCompression newCompression)
    : m_document(document),
      m_slot(slot),
      m_old(std::move(oldCompression)),
      m_new(std::move(newCompression)) {
  const QString label = toQString(core::mapSlotLabel(slot));
  setText(!m_new ? QObject::tr("%1 map: no compression").arg(label)
                 : QObject::tr("%1 map: compress as %2 (%3)")
                       .arg(label, toQString(core::textureFormatInfo(m_new->format).name),
                            toQString(core::compressionQualityName(m_new->quality))));
}

void SetCompressionCommand::undo() {
  m_document->applyCompression(m_slot, m_old);
}
void SetCompressionCommand::redo() {
  m_document->applyCompression(m_slot, m_new);
}

SetMapCommand::SetMapCommand(MaterialDocument* document, core::MapSlot slot,
                             core::MaterialMap oldMap, core::MaterialMap newMap)
    : m_document(document), m_slot(slot), m_oldMap(std::move(oldMap)), m_newMap(std::move(newMap)) {
  const QString label = toQString(core::mapSlotLabel(slot));
  setText(m_newMap.image
              ? QObject::tr("Load %1 map (%2)")
                    .arg(label, QFileInfo(QString::fromStdString(m_newMap.sourcePath)).fileName())
              : QObject::tr("Clear %1 map").arg(label));
}

void SetMapCommand::undo() {
  m_document->applyMap(m_slot, m_oldMap);
}
void SetMapCommand::redo() {
  m_document->applyMap(m_slot, m_newMap);
}

}  // namespace relief::ui::inline document
