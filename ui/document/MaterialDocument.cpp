// MaterialDocument; see MaterialDocument.h.
#include "ui/document/MaterialDocument.h"

#include "ui/document/MaterialCommands.h"

#include <QFileInfo>

namespace relief::ui::inline document {

MaterialDocument::MaterialDocument(QObject* parent) : QObject(parent) {}

void MaterialDocument::reset(core::Material material, const QString& filePath) {
  core::Preset preset;
  preset.material = std::move(material);
  reset(std::move(preset), filePath);
}

void MaterialDocument::reset(core::Preset preset, const QString& filePath) {
  m_material = std::move(preset.material);
  m_compression = preset.compression;
  m_preserved = std::move(preset.preserved);
  m_filePath = filePath;
  m_undoStack.clear();
  Q_EMIT materialReset();
}

core::Preset MaterialDocument::toPreset(const core::ViewState& view) const {
  core::Preset preset;
  preset.material = m_material;
  preset.view = view;
  preset.compression = m_compression;
  preset.preserved = m_preserved;
  return preset;
}

core::Result<core::SavedPreset> MaterialDocument::save(const QString& path,
                                                       const core::ViewState& view) {
  core::Preset preset = toPreset(view);
  // A material named after its file follows the file (Save As "mossy.relief" names it mossy);
  // a name the artist chose stays.
  const std::string oldStem = QFileInfo(m_filePath).completeBaseName().toStdString();
  if (preset.material.name().empty() || preset.material.name() == oldStem)
    preset.material.setName(QFileInfo(path).completeBaseName().toStdString());
  core::Result<core::SavedPreset> saved = core::savePreset(preset, path.toStdString());
  if (!saved)
    return saved;
  m_material.setName(preset.material.name());
  // The written files are now the maps' sources; undo history keeps the images themselves, so
  // only the path changes here.
  for (const auto& [slot, writtenPath] : saved->writtenMaps)
    m_material.setMap(slot, m_material.map(slot).image, writtenPath);
  m_filePath = path;
  m_undoStack.setClean();
  Q_EMIT fileSaved();
  return saved;
}

void MaterialDocument::setParameter(core::ParamId id, double value, int interactiveEdit) {
  const double sanitized = core::sanitizeOptionValue(core::parameterSpec(id), value);
  if (sanitized == m_material.parameter(id))
    return;
  m_undoStack.push(
      new SetParameterCommand(this, id, m_material.parameter(id), sanitized, interactiveEdit));
}

void MaterialDocument::resetParameters() {
  if (m_material.parameters() == core::defaultParameterValues())
    return;
  m_undoStack.push(
      new SetAllParametersCommand(this, m_material.parameters(), core::defaultParameterValues()));
}

void MaterialDocument::setCompression(core::MapSlot slot, const core::MapCompression& compression) {
  if (compression == m_compression[std::size_t(slot)])
    return;
  m_undoStack.push(
      new SetCompressionCommand(this, slot, m_compression[std::size_t(slot)], compression));
}

void MaterialDocument::applyCompression(core::MapSlot slot,
                                        const core::MapCompression& compression) {
  m_compression[std::size_t(slot)] = compression;
  Q_EMIT compressionChanged(slot);
}

void MaterialDocument::setTechnique(core::Technique technique) {
  if (technique == m_material.technique())
    return;
  m_undoStack.push(new SetTechniqueCommand(this, m_material.technique(), technique));
}

void MaterialDocument::setMap(core::MapSlot slot, std::shared_ptr<const core::Image> image,
                              const QString& sourcePath, int sourceChannel) {
  core::Material probe;  // tags the image with the slot's colour space, as the material would
  probe.setMap(slot, std::move(image), sourcePath.toStdString(), sourceChannel);
  m_undoStack.push(new SetMapCommand(this, slot, m_material.map(slot), probe.map(slot)));
}

void MaterialDocument::applyGenerated(
    core::MapSlot slot, std::shared_ptr<const core::Image> image, const QString& label,
    const std::vector<std::pair<core::ParamId, double>>& parameterChanges) {
  m_undoStack.beginMacro(label);
  setMap(slot, std::move(image), QString());
  for (const auto& [id, value] : parameterChanges)
    setParameter(id, value);
  m_undoStack.endMacro();
}

void MaterialDocument::applyMaps(
    const std::vector<std::pair<core::MapSlot, std::shared_ptr<const core::Image>>>& maps,
    const QString& label) {
  m_undoStack.beginMacro(label);
  for (const auto& [slot, image] : maps)
    setMap(slot, image, QString());
  m_undoStack.endMacro();
}

void MaterialDocument::applyLook(const core::Material& from, const QString& label) {
  if (from.technique() == m_material.technique() && from.parameters() == m_material.parameters())
    return;
  m_undoStack.beginMacro(label);
  setTechnique(from.technique());
  if (from.parameters() != m_material.parameters()) {
    m_undoStack.push(new SetAllParametersCommand(this, m_material.parameters(), from.parameters()));
  }
  m_undoStack.endMacro();
}

void MaterialDocument::clearMap(core::MapSlot slot) {
  if (!m_material.hasMap(slot))
    return;
  m_undoStack.push(new SetMapCommand(this, slot, m_material.map(slot), core::MaterialMap{}));
}

void MaterialDocument::applyParameter(core::ParamId id, double value) {
  m_material.setParameter(id, value);
  Q_EMIT parameterChanged(id);
}

void MaterialDocument::applyParameters(const core::ParameterValues& values) {
  for (const core::ParameterSpec& spec : core::allParameters()) {
    applyParameter(spec.id, values[std::size_t(spec.id)]);
  }
}

void MaterialDocument::applyTechnique(core::Technique technique) {
  m_material.setTechnique(technique);
  Q_EMIT techniqueChanged();
}

void MaterialDocument::applyMap(core::MapSlot slot, const core::MaterialMap& map) {
  m_material.setMap(slot, map.image, map.sourcePath, map.sourceChannel);
  Q_EMIT mapChanged(slot);
}

}  // namespace relief::ui::inline document
