// MapCheckCommand; see MapCheckCommand.h.
#include "MapCheckCommand.h"

#include "app/cli/CliOptionNames.h"

#include "CliCommon.h"
#include "core/compression/Compressor.h"
#include "core/compression/TextureFile.h"
#include "core/generators/MapCheck.h"
#include "core/image/ImageIO.h"
#include "core/preset/MaterialPreset.h"

#include <QFileInfo>
#include <QJsonArray>

#include <memory>

namespace relief::cli {
namespace {

// The maps to check, what the material declares of them, and their names for the messages.
struct CheckedMaps {
  std::shared_ptr<const core::Image> normal, height;
  QString normalName, heightName;
  core::NormalConvention declaredConvention = core::NormalConvention::OpenGl;
  bool declaredDepth = false;
};

CliOptions checkOptions() {
  return {
      {option::kCheck, {}, QStringLiteral("Check the maps against each other (this command)."), {}},
      {option::kNormal,
       QStringLiteral("file"),
       QStringLiteral("The normal map, without a preset (read as OpenGL, +Y up)."),
       {}},
      {option::kHeight,
       QStringLiteral("file"),
       QStringLiteral("The height map, without a preset (read as height, white on top)."),
       {}},
      jsonOption(),
  };
}

std::optional<int> mapsFromPreset(const QString& path, CheckedMaps& maps) {
  core::Result<core::LoadedPreset> loaded = core::loadPreset(path.toStdString());
  if (!loaded) {
    printError(QString::fromStdString(loaded.error()));
    return kExitFailure;
  }
  if (!acceptPresetProblems(loaded->warnings, false))
    return kExitFailure;
  const core::Material& material = loaded->preset.material;
  const core::MaterialMap& normal = material.map(core::MapSlot::Normal);
  if (!normal.image) {
    printError(QStringLiteral("%1: the preset has no normal map to check").arg(path));
    return kExitFailure;
  }
  maps.normal = normal.image;
  maps.normalName = QFileInfo(QString::fromStdString(normal.sourcePath)).fileName();
  if (material.parameterFlag(core::ParamId::HeightInNormalAlpha) && normal.image->channels() == 4) {
    maps.height = std::make_shared<core::Image>(core::channelImage(*normal.image, 3));
    maps.heightName = maps.normalName + QStringLiteral(" (alpha)");
  } else if (const core::MaterialMap& height = material.map(core::MapSlot::Height); height.image) {
    maps.height = height.image;
    maps.heightName = QFileInfo(QString::fromStdString(height.sourcePath)).fileName();
  }
  maps.declaredConvention = material.parameterFlag(core::ParamId::NormalYDown)
                                ? core::NormalConvention::DirectX
                                : core::NormalConvention::OpenGl;
  maps.declaredDepth = material.parameterFlag(core::ParamId::HeightIsDepth);
  return std::nullopt;
}

// An image file, or the first level of a DDS or KTX2 texture decoded as the GPU would (game
// data ships many normal maps only as BC3 or BC5).
core::Result<core::Image> loadMap(const std::string& path) {
  if (!core::containerForPath(path))
    return core::loadImage(path);
  core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(path);
  if (!texture)
    return core::makeError(texture.error());
  return core::decodeLevel(texture.value());
}

std::optional<int> mapFromFile(const QString& path, std::shared_ptr<const core::Image>& image,
                               QString& name) {
  core::Result<core::Image> loaded = loadMap(path.toStdString());
  if (!loaded) {
    printError(QString::fromStdString(loaded.error()));
    return kExitFailure;
  }
  image = std::make_shared<core::Image>(std::move(loaded).value());
  name = QFileInfo(path).fileName();
  return std::nullopt;
}

QString conventionName(std::optional<core::NormalConvention> convention) {
  if (!convention)
    return QStringLiteral("unknown");
  return *convention == core::NormalConvention::DirectX ? QStringLiteral("directx")
                                                        : QStringLiteral("opengl");
}

void printResult(const CheckedMaps& maps, const core::MapCheckResult& result,
                 const std::vector<std::string>& findings, bool json) {
  if (json) {
    QJsonObject object{
        {QStringLiteral("normal"), maps.normalName},
        {QStringLiteral("height"), maps.height ? QJsonValue(maps.heightName) : QJsonValue()},
        {QStringLiteral("ok"), findings.empty()},
        {QStringLiteral("convention"), conventionName(result.convention)},
        {QStringLiteral("curlAsStored"), result.curlAsStored},
        {QStringLiteral("curlFlipped"), result.curlFlipped},
    };
    if (maps.height) {
      object.insert(QStringLiteral("pairMatches"), result.pairMatches);
      object.insert(QStringLiteral("heightIsDepth"),
                    result.heightIsDepth ? QJsonValue(*result.heightIsDepth) : QJsonValue());
      object.insert(QStringLiteral("correlationX"), *result.correlationX);
      object.insert(QStringLiteral("correlationY"), *result.correlationY);
      object.insert(QStringLiteral("strength"),
                    result.strength ? QJsonValue(*result.strength) : QJsonValue());
    }
    QJsonArray list;
    for (const std::string& finding : findings)
      list.append(QString::fromStdString(finding));
    object.insert(QStringLiteral("findings"), list);
    printJson(object);
    return;
  }
  QString text = QStringLiteral("normal map: %1 (%2; curl as stored %3x that with Y flipped)\n")
                     .arg(maps.normalName, conventionName(result.convention))
                     .arg(result.curlFlipped > 0.0 ? result.curlAsStored / result.curlFlipped : 1.0,
                          0, 'f', 2);
  if (maps.height) {
    text += QStringLiteral("height map: %1 (slopes correlate by x %2, y %3; %4)\n")
                .arg(maps.heightName)
                .arg(*result.correlationX, 0, 'f', 2)
                .arg(*result.correlationY, 0, 'f', 2)
                .arg(!result.pairMatches     ? QStringLiteral("not the same surface")
                     : !result.heightIsDepth ? QStringLiteral("height or depth: unknown")
                     : *result.heightIsDepth ? QStringLiteral("depth")
                                             : QStringLiteral("height"));
    if (result.strength)
      text += QStringLiteral("normal strength from height: %1\n").arg(*result.strength, 0, 'f', 2);
  }
  for (const std::string& finding : findings)
    text += QStringLiteral("problem: %1\n").arg(QString::fromStdString(finding));
  if (findings.empty())
    text += QStringLiteral("the maps agree with each other and with the material\n");
  printOut(text);
}

}  // namespace

int runMapCheck(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Check a material's normal and height maps against each other and against what the "
      "preset declares: the normal map's Y convention (OpenGL or DirectX), whether the height "
      "map stores depth, and whether the two describe the same surface, with the evidence. "
      "Exits 1 when it finds a problem."));
  parser.addPositionalArgument(QStringLiteral("preset"),
                               QStringLiteral("A .relief preset (or give --normal and --height)."));
  addOptions(parser, checkOptions());
  const QString usage =
      QStringLiteral("relief-cli info --check <preset.relief> | --normal FILE [--height FILE]");
  if (auto exit = parseOrExit(parser, arguments, usage))
    return *exit;
  const QStringList positional = parser.positionalArguments();
  CheckedMaps maps;
  if (positional.size() == 1 && !parser.isSet(option::kNormal) && !parser.isSet(option::kHeight)) {
    if (auto exit = mapsFromPreset(positional.front(), maps))
      return *exit;
  } else if (positional.isEmpty() && parser.isSet(option::kNormal)) {
    if (auto exit = mapFromFile(parser.value(option::kNormal), maps.normal, maps.normalName))
      return *exit;
    if (parser.isSet(option::kHeight)) {
      if (auto exit = mapFromFile(parser.value(option::kHeight), maps.height, maps.heightName))
        return *exit;
    }
  } else {
    printError(
        QStringLiteral("info --check takes a preset, or --normal FILE and optionally "
                       "--height FILE (see --help)"));
    return kExitUsage;
  }
  core::Result<core::MapCheckResult> result = core::checkMaps(*maps.normal, maps.height.get());
  if (!result) {
    printError(QStringLiteral("%1%2: %3")
                   .arg(maps.normalName,
                        maps.height ? QStringLiteral(" and ") + maps.heightName : QString(),
                        QString::fromStdString(result.error())));
    return kExitFailure;
  }
  const std::vector<std::string> findings =
      core::mapCheckFindings(result.value(), maps.declaredConvention, maps.declaredDepth,
                             maps.normalName.toStdString(), maps.heightName.toStdString());
  printResult(maps, result.value(), findings, parser.isSet(option::kJson));
  return findings.empty() ? kExitOk : kExitFailure;
}

}  // namespace relief::cli
