// Preset files; see MaterialPreset.h.
#include "core/MaterialPreset.h"

#include "core/ImageIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

#include <cmath>

namespace relief::core {
namespace {

QString qstr(std::string_view text) {
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

void readParameters(const QJsonObject& object, const std::string& path, Material& material,
                    std::vector<std::string>& warnings) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string key = it.key().toStdString();
    const std::optional<ParamId> id = findParameter(key);
    if (!id) {
      warnings.push_back(path + ": unknown parameter '" + key + "' ignored");
      continue;
    }
    const ParameterSpec& spec = parameterSpec(*id);
    double value = 0.0;
    if (it.value().isBool() && spec.kind == ParamKind::Bool) {
      value = it.value().toBool() ? 1.0 : 0.0;
    } else if (it.value().isString() && spec.kind == ParamKind::Choice) {
      Result<double> parsed = parseOptionValue(spec, it.value().toString().toStdString());
      if (!parsed) {
        warnings.push_back(path + ": " + parsed.error() + "; default kept");
        continue;
      }
      value = parsed.value();
    } else if (it.value().isDouble()) {
      value = it.value().toDouble();
    } else {
      warnings.push_back(path + ": parameter '" + key + "' has the wrong type; default kept");
      continue;
    }
    if (!std::isfinite(value)) {
      warnings.push_back(path + ": parameter '" + key + "' is not a finite number; default kept");
      continue;
    }
    const double sanitized = sanitizeOptionValue(spec, value);
    if (sanitized != value) {
      warnings.push_back(path + ": parameter '" + key + "' = " + std::to_string(value) +
                         " is outside its range; clamped to " + std::to_string(sanitized));
    }
    material.setParameter(*id, sanitized);
  }
}

void readMaps(const QJsonObject& object, const std::string& path, Material& material,
              std::vector<std::string>& warnings) {
  const QDir presetDir = QFileInfo(QString::fromStdString(path)).absoluteDir();
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::optional<MapSlot> slot = findMapSlot(it.key().toStdString());
    if (!slot) {
      warnings.push_back(path + ": unknown map slot '" + it.key().toStdString() + "' ignored");
      continue;
    }
    const QString relative = it.value().toObject().value(QStringLiteral("path")).toString();
    if (relative.isEmpty()) {
      warnings.push_back(path + ": map '" + it.key().toStdString() + "' has no path");
      continue;
    }
    const std::string mapPath = QDir::cleanPath(presetDir.absoluteFilePath(relative)).toStdString();
    Result<Image> image = loadImage(mapPath);
    if (!image) {
      warnings.push_back(path + ": " + it.key().toStdString() +
                         " map not loaded: " + image.error());
      continue;
    }
    material.setMap(*slot, std::make_shared<Image>(std::move(image).value()), mapPath);
  }
}

}  // namespace

Result<LoadedPreset> loadPreset(const std::string& path) {
  QFile file(QString::fromStdString(path));
  if (!file.exists()) {
    return makeError(path + ": file not found");
  }
  if (!file.open(QIODevice::ReadOnly)) {
    return makeError(path + ": cannot open (" + file.errorString().toStdString() + ")");
  }
  QJsonParseError parseError;
  const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &parseError);
  if (parseError.error != QJsonParseError::NoError) {
    return makeError(path + ": not a valid preset: " + parseError.errorString().toStdString() +
                     " at byte " + std::to_string(parseError.offset));
  }
  if (!document.isObject()) {
    return makeError(path + ": not a valid preset: the top level is not a JSON object");
  }
  const QJsonObject root = document.object();
  if (root.value(QStringLiteral("format")).toString() != qstr(kPresetFormatName)) {
    return makeError(path + ": not a Relief preset (\"format\" is not \"" +
                     std::string(kPresetFormatName) + "\")");
  }
  const QJsonValue versionValue = root.value(QStringLiteral("version"));
  const double version = versionValue.toDouble(-1);
  if (!versionValue.isDouble() || version != std::floor(version) || version < 1) {
    return makeError(path + ": \"version\" must be a positive integer");
  }
  if (version > kPresetVersion) {
    return makeError(path + ": written by a newer Relief (preset version " +
                     std::to_string(int(version)) + "; this program reads up to " +
                     std::to_string(kPresetVersion) + ")");
  }

  LoadedPreset loaded;
  Material& material = loaded.material;
  material.setName(root.value(QStringLiteral("name"))
                       .toString(QFileInfo(QString::fromStdString(path)).completeBaseName())
                       .toStdString());
  if (root.contains(QStringLiteral("technique"))) {
    const std::string name = root.value(QStringLiteral("technique")).toString().toStdString();
    if (const std::optional<Technique> technique = findTechnique(name)) {
      material.setTechnique(*technique);
    } else {
      loaded.warnings.push_back(path + ": unknown technique '" + name + "'; using " +
                                std::string(techniqueName(material.technique())));
    }
  }
  readParameters(root.value(QStringLiteral("parameters")).toObject(), path, material,
                 loaded.warnings);
  readMaps(root.value(QStringLiteral("maps")).toObject(), path, material, loaded.warnings);
  return loaded;
}

Status savePreset(const Material& material, const std::string& path) {
  const QDir presetDir = QFileInfo(QString::fromStdString(path)).absoluteDir();
  QJsonObject root;
  root.insert(QStringLiteral("format"), qstr(kPresetFormatName));
  root.insert(QStringLiteral("version"), kPresetVersion);
  if (!material.name().empty()) {
    root.insert(QStringLiteral("name"), QString::fromStdString(material.name()));
  }
  QJsonObject maps;
  for (MapSlot slot : kAllMapSlots) {
    const MaterialMap& map = material.map(slot);
    if (!map.image || map.sourcePath.empty())
      continue;
    QJsonObject entry;
    entry.insert(QStringLiteral("path"),
                 presetDir.relativeFilePath(QString::fromStdString(map.sourcePath)));
    entry.insert(QStringLiteral("colorSpace"), qstr(colorSpaceName(mapSlotColorSpace(slot))));
    maps.insert(qstr(mapSlotName(slot)), entry);
  }
  root.insert(QStringLiteral("maps"), maps);
  root.insert(QStringLiteral("technique"), qstr(techniqueName(material.technique())));
  QJsonObject parameters;
  for (const ParameterSpec& spec : allParameters()) {
    const double value = material.parameter(spec.id);
    switch (spec.kind) {
      case ParamKind::Bool:
        parameters.insert(qstr(spec.name), value != 0.0);
        break;
      case ParamKind::Choice:
        parameters.insert(qstr(spec.name), qstr(spec.choices[std::size_t(value)]));
        break;
      default:
        parameters.insert(qstr(spec.name), value);
    }
  }
  root.insert(QStringLiteral("parameters"), parameters);

  QSaveFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::WriteOnly)) {
    return makeError(path + ": cannot write (" + file.errorString().toStdString() + ")");
  }
  file.write(QJsonDocument(root).toJson(QJsonDocument::Indented));
  if (!file.commit()) {
    return makeError(path + ": cannot write (" + file.errorString().toStdString() + ")");
  }
  return {};
}

}  // namespace relief::core
