// PresetCommand; see PresetCommand.h.
#include "PresetCommand.h"

#include "CliCommon.h"
#include "core/image/Image.h"
#include "core/preset/MaterialPreset.h"

#include <QJsonArray>
#include <QJsonObject>

namespace relief::cli {
namespace {

const char* kUsage =
    "Usage: relief-cli preset <validate|info> <preset.relief> [--json]\n"
    "\n"
    "  validate  Load the preset and its maps as the editor does. Exit 0 and a summary when\n"
    "            nothing is wrong; exit 1 and every problem (a missing map, a value out of\n"
    "            range, a wrong type, an unknown key) when something is.\n"
    "  info      Print the preset's technique, parameters, maps, compression choices and\n"
    "            view. Problems are printed too, as warnings.\n"
    "  --json    Either: one JSON object on standard output instead (validity, problems,\n"
    "            technique, maps with sizes and compression, parameters by name).\n";

QString mapsSummary(const core::Material& material) {
  QStringList parts;
  for (core::MapSlot slot : core::kAllMapSlots) {
    if (const core::Image* image = material.image(slot)) {
      parts << QStringLiteral("%1 %2x%3")
                   .arg(qstr(core::mapSlotName(slot)))
                   .arg(image->width())
                   .arg(image->height());
    }
  }
  return parts.isEmpty() ? QStringLiteral("none") : parts.join(QStringLiteral(", "));
}

// The preset as one JSON object: validity and problems, then what it holds.
QJsonObject presetJson(const QString& path, const core::LoadedPreset& loaded) {
  const core::Material& material = loaded.preset.material;
  QJsonArray problems;
  for (const std::string& warning : loaded.warnings)
    problems.append(QString::fromStdString(warning));
  QJsonObject maps;
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MaterialMap& map = material.map(slot);
    if (!map.image)
      continue;
    QJsonObject entry{{QStringLiteral("file"), QString::fromStdString(map.sourcePath)},
                      {QStringLiteral("width"), map.image->width()},
                      {QStringLiteral("height"), map.image->height()},
                      {QStringLiteral("channels"), map.image->channels()}};
    if (map.sourceChannel >= 0)
      entry.insert(QStringLiteral("channel"),
                   QString(QChar::fromLatin1(core::channelLetter(map.sourceChannel))));
    if (const core::MapCompression& compression = loaded.preset.compression[std::size_t(slot)]) {
      entry.insert(
          QStringLiteral("compression"),
          QJsonObject{
              {QStringLiteral("format"), qstr(core::textureFormatInfo(compression->format).name)},
              {QStringLiteral("quality"), qstr(core::compressionQualityName(compression->quality))},
              {QStringLiteral("mipmaps"), compression->mipmaps}});
    }
    maps.insert(qstr(core::mapSlotName(slot)), entry);
  }
  QJsonObject parameters;
  for (const core::ParameterSpec& spec : core::allParameters())
    parameters.insert(qstr(spec.name), material.parameter(spec.id));
  return {{QStringLiteral("file"), path},
          {QStringLiteral("valid"), loaded.warnings.empty()},
          {QStringLiteral("problems"), problems},
          {QStringLiteral("format"), qstr(core::kPresetFormatName)},
          {QStringLiteral("fileVersion"), loaded.fileVersion},
          {QStringLiteral("name"), QString::fromStdString(material.name())},
          {QStringLiteral("technique"), qstr(core::techniqueName(material.technique()))},
          {QStringLiteral("maps"), maps},
          {QStringLiteral("parameters"), parameters}};
}

int validate(const QString& path, bool json) {
  if (json) {
    core::Result<core::LoadedPreset> loaded = core::loadPreset(path.toStdString());
    if (!loaded) {
      printError(QString::fromStdString(loaded.error()));
      return kExitFailure;
    }
    printJson(presetJson(path, loaded.value()));
    return loaded->warnings.empty() ? kExitOk : kExitFailure;
  }
  core::Result<core::LoadedPreset> loaded = core::loadPreset(path.toStdString());
  if (!loaded) {
    printError(QString::fromStdString(loaded.error()));
    return kExitFailure;
  }
  if (!loaded->warnings.empty()) {
    for (const std::string& warning : loaded->warnings)
      printError(QString::fromStdString(warning));
    printError(QStringLiteral("%1: %2 problem(s)").arg(path).arg(loaded->warnings.size()));
    return kExitFailure;
  }
  const core::Material& material = loaded->preset.material;
  QString version = QString::number(core::kPresetVersion);
  if (loaded->fileVersion != core::kPresetVersion) {
    version = QStringLiteral("%1 (read as %2; saving writes %2)")
                  .arg(loaded->fileVersion)
                  .arg(core::kPresetVersion);
  }
  printOut(QStringLiteral("%1: valid (format %2 version %3)\n  technique %4; maps: %5\n")
               .arg(path, qstr(core::kPresetFormatName), version,
                    qstr(core::techniqueName(material.technique())), mapsSummary(material)));
  return kExitOk;
}

int info(const QString& path, bool json) {
  core::Result<core::LoadedPreset> loaded = core::loadPreset(path.toStdString());
  if (!loaded) {
    printError(QString::fromStdString(loaded.error()));
    return kExitFailure;
  }
  if (json) {
    printJson(presetJson(path, loaded.value()));
    return kExitOk;
  }
  for (const std::string& warning : loaded->warnings)
    printError(QStringLiteral("warning: ") + QString::fromStdString(warning));
  const core::Preset& preset = loaded->preset;
  const core::Material& material = preset.material;
  QString text = QStringLiteral("file: %1\nformat: %2 version %3\nname: %4\ntechnique: %5 (%6)\n")
                     .arg(path, qstr(core::kPresetFormatName))
                     .arg(loaded->fileVersion)
                     .arg(QString::fromStdString(material.name()),
                          qstr(core::techniqueName(material.technique())),
                          qstr(core::techniqueLabel(material.technique())));
  text += QStringLiteral("maps:\n");
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MaterialMap& map = material.map(slot);
    if (!map.image)
      continue;
    QString source = QString::fromStdString(map.sourcePath);
    if (map.sourceChannel >= 0)
      source += QStringLiteral(" channel %1")
                    .arg(QChar::fromLatin1(core::channelLetter(map.sourceChannel)).toUpper());
    text += QStringLiteral("  %1 %2 (%3x%4, %5 channel(s), %6 bit, %7)")
                .arg(qstr(core::mapSlotName(slot)) + QLatin1Char(':'), -10)
                .arg(source)
                .arg(map.image->width())
                .arg(map.image->height())
                .arg(map.image->channels())
                .arg(map.image->sourceBitsPerChannel())
                .arg(qstr(core::colorSpaceName(map.image->colorSpace())));
    const core::MapCompression& compression = preset.compression[std::size_t(slot)];
    if (compression) {
      text += QStringLiteral(" compress %1 %2%3")
                  .arg(qstr(core::textureFormatInfo(compression->format).name),
                       qstr(core::compressionQualityName(compression->quality)),
                       compression->mipmaps ? QStringLiteral(" mipmaps") : QString());
    }
    text += QLatin1Char('\n');
  }
  text += QStringLiteral("parameters:\n");
  for (const core::ParameterSpec& spec : core::allParameters()) {
    text += QStringLiteral("  %1 = %2\n")
                .arg(qstr(spec.name), -20)
                .arg(QString::fromStdString(
                    core::formatOptionValue(spec, material.parameter(spec.id))));
  }
  if (preset.view.camera) {
    const core::OrbitCamera& c = *preset.view.camera;
    text += QStringLiteral("camera: yaw %1, pitch %2, distance %3, fov %4, target (%5, %6, %7)\n")
                .arg(c.yawDeg)
                .arg(c.pitchDeg)
                .arg(c.distance)
                .arg(c.fovYDeg)
                .arg(c.target.x)
                .arg(c.target.y)
                .arg(c.target.z);
  }
  if (preset.view.light) {
    const core::DirectionalLight& l = *preset.view.light;
    text += QStringLiteral(
                "light: azimuth %1, elevation %2, intensity %3, ambient %4, colour "
                "(%5, %6, %7)\n")
                .arg(l.azimuthDeg)
                .arg(l.elevationDeg)
                .arg(l.intensity)
                .arg(l.ambient)
                .arg(l.color.r)
                .arg(l.color.g)
                .arg(l.color.b);
  }
  if (!preset.view.mesh.empty())
    text += QStringLiteral("mesh: %1\n").arg(QString::fromStdString(preset.view.mesh));
  printOut(text);
  return kExitOk;
}

}  // namespace

int runPreset(const QStringList& arguments) {
  // arguments: program, "preset", action, file
  if (arguments.size() >= 3 &&
      (arguments[2] == QStringLiteral("--help") || arguments[2] == QStringLiteral("-h"))) {
    printOut(QString::fromUtf8(kUsage));
    return kExitOk;
  }
  QStringList rest = arguments;
  const bool json = rest.removeAll(QStringLiteral("--json")) > 0;
  if (rest.size() != 4) {
    printError(QStringLiteral("preset takes an action and one file"));
    printOut(QString::fromUtf8(kUsage));
    return kExitUsage;
  }
  const QString& action = rest[2];
  if (action == QStringLiteral("validate"))
    return validate(rest[3], json);
  if (action == QStringLiteral("info"))
    return info(rest[3], json);
  printError(QStringLiteral("preset: unknown action '%1' (validate or info)").arg(action));
  return kExitUsage;
}

}  // namespace relief::cli
