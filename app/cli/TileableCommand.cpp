// TileableCommand; see TileableCommand.h.
#include "TileableCommand.h"

#include "app/cli/CliOptionNames.h"

#include "CliCommon.h"
#include "TerminalProgress.h"
#include "core/compression/MapFile.h"
#include "core/generators/Generators.h"
#include "core/generators/Tileable.h"
#include "core/image/ImageIO.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <array>

namespace relief::cli {
namespace {

struct MethodName {
  const char* name;
  core::TileMethod value;
};
constexpr std::array kMethods = {MethodName{"quilt", core::TileMethod::Quilt},
                                 MethodName{"crossfade", core::TileMethod::CrossFade}};

CliOptions tileableOptions() {
  return {
      {option::kIn,
       QStringLiteral("file"),
       QStringLiteral("The photo (or any map of the set)."),
       {}},
      {option::kAlso,
       QStringLiteral("file"),
       QStringLiteral("Another map aligned with it (height, normal, roughness...), cut the same "
                      "way; repeat for each. Normal maps are recognised by their content and "
                      "blended as vectors."),
       {}},
      {option::kOutDir,
       QStringLiteral("folder"),
       QStringLiteral("Where the tiles are written, under their input names (created if "
                      "missing; never an input's own folder)."),
       {}},
      {option::kMethod, QStringLiteral("name"),
       QStringLiteral("quilt: a patch of the photo laid over each seam, cut along the "
                      "least visible path (structured textures); crossfade: blended with itself "
                      "shifted, keeping its histogram (stochastic textures)."),
       QStringLiteral("quilt")},
      {option::kPatch, QStringLiteral("texels"),
       QStringLiteral("quilt: the patch's width (its outer thirds are cut in); 0 picks a third of "
                      "the shorter side."),
       QStringLiteral("0")},
      {option::kFeather, QStringLiteral("texels"),
       QStringLiteral("quilt: texels blended on each side of a cut."), QStringLiteral("2")},
      {option::kRecut, {}, QStringLiteral("Remake an axis even when it already tiles."), {}},
      jsonOption(),
  };
}

QJsonObject axisJson(const core::TileAxisReport& axis, core::TileMethod method) {
  QJsonObject object{{QStringLiteral("alreadyTiled"), axis.alreadyTiled},
                     {QStringLiteral("seamBefore"), axis.seamBefore},
                     {QStringLiteral("seamAfter"), axis.seamAfter}};
  if (!axis.alreadyTiled) {
    object.insert(
        method == core::TileMethod::Quilt ? QStringLiteral("patchSource") : QStringLiteral("shift"),
        axis.source);
    if (method == core::TileMethod::Quilt)
      object.insert(QStringLiteral("cutRatio"), axis.cutRatio);
  }
  return object;
}

QString axisLine(const char* name, const core::TileAxisReport& axis, core::TileMethod method) {
  const QString seam = QStringLiteral("%1: wrap seam %2x the interior's texel-to-texel contrast")
                           .arg(QLatin1String(name))
                           .arg(axis.seamBefore, 0, 'f', 2);
  if (axis.alreadyTiled)
    return seam + QStringLiteral(", already tiles: left as it was\n");
  if (method == core::TileMethod::Quilt)
    return seam + QStringLiteral(" -> %1x (patch from %2 %3, cuts %4x)\n")
                      .arg(axis.seamAfter, 0, 'f', 2)
                      .arg(QLatin1String(name[0] == 'h' ? "column" : "row"))
                      .arg(axis.source)
                      .arg(axis.cutRatio, 0, 'f', 2);
  return seam + QStringLiteral(" -> %1x (cross-faded with itself shifted by %2)\n")
                    .arg(axis.seamAfter, 0, 'f', 2)
                    .arg(axis.source);
}

}  // namespace

int runTileable(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Make a photo and the maps aligned with it tile seamlessly: the same cut for every map, "
      "so they stay aligned. An axis that already tiles is left as it is."));
  addOptions(parser, tileableOptions());
  QStringList withoutGenerator = arguments;
  withoutGenerator.removeAt(2);
  if (auto exit = parseOrExit(parser, withoutGenerator,
                              QStringLiteral("relief-cli generate tileable --in PHOTO [--also MAP "
                                             "...] --out-dir DIR [options]")))
    return *exit;
  if (!parser.positionalArguments().isEmpty()) {
    printError(QStringLiteral("generate tileable: unexpected argument '%1' (see --help)")
                   .arg(parser.positionalArguments().front()));
    return kExitUsage;
  }
  if (const QString missing = missingOptions(parser, {option::kIn, option::kOutDir});
      !missing.isEmpty()) {
    printError(QStringLiteral("generate tileable needs ") + missing);
    return kExitUsage;
  }
  core::TileableOptions options;
  const auto method = namedOption(parser, option::kMethod, kMethods);
  const auto patch = integerOption(parser, option::kPatch, 0, 0, core::kMaxImageDimension);
  const auto feather = integerOption(parser, option::kFeather, 2, 0, 64);
  if (!method || !patch || !feather)
    return kExitUsage;
  options.method = *method;
  options.patch = *patch;
  options.feather = *feather;
  options.recut = parser.isSet(option::kRecut);

  const QStringList inputs = QStringList{parser.value(option::kIn)} + parser.values(option::kAlso);
  const QDir outDir(parser.value(option::kOutDir));
  std::vector<core::Image> images;
  std::vector<core::TileMap> maps;
  QStringList outputs;
  for (const QString& input : inputs) {
    const QString output = outDir.filePath(QFileInfo(input).fileName());
    if (QFileInfo(output).absoluteFilePath() == QFileInfo(input).absoluteFilePath()) {
      printError(QStringLiteral("generate tileable: %1 would be written over itself; give an "
                                "--out-dir other than its folder")
                     .arg(input));
      return kExitUsage;
    }
    if (outputs.contains(output)) {
      printError(QStringLiteral("generate tileable: two inputs are named %1; their tiles would "
                                "overwrite each other")
                     .arg(QFileInfo(input).fileName()));
      return kExitUsage;
    }
    core::Result<core::Image> image = core::loadMapFile(input.toStdString());
    if (!image) {
      printError(QString::fromStdString(image.error()));
      return kExitFailure;
    }
    images.push_back(std::move(image).value());
    outputs << output;
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    const bool normal = images[i].channels() >= 3 && !core::normalMapWarning(images[i]);
    maps.push_back({&images[i], normal ? core::TileMapRole::Normal : core::TileMapRole::Data});
  }

  core::Result<core::TileableResult> result = [&] {
    TerminalProgress progress(QStringLiteral("generate tileable"));
    return core::makeTileable(maps, options, progress.control());
  }();
  if (!result) {
    printError(QStringLiteral("%1: %2").arg(inputs.join(QStringLiteral(", ")),
                                            QString::fromStdString(result.error())));
    return kExitFailure;
  }
  if (!QDir().mkpath(outDir.path())) {
    printError(QStringLiteral("generate tileable: cannot create the folder %1").arg(outDir.path()));
    return kExitFailure;
  }
  for (std::size_t i = 0; i < result->maps.size(); ++i) {
    if (core::Status saved = core::saveImage(result->maps[i], outputs[int(i)].toStdString());
        !saved) {
      printError(QString::fromStdString(saved.error()));
      return kExitFailure;
    }
  }
  if (parser.isSet(option::kJson)) {
    QJsonArray written;
    for (std::size_t i = 0; i < maps.size(); ++i)
      written.append(
          QJsonObject{{QStringLiteral("input"), inputs[int(i)]},
                      {QStringLiteral("output"), outputs[int(i)]},
                      {QStringLiteral("normal"), maps[i].role == core::TileMapRole::Normal}});
    printJson(
        {{QStringLiteral("generator"), QStringLiteral("tileable")},
         {QStringLiteral("method"), QLatin1String(kMethods[std::size_t(options.method)].name)},
         {QStringLiteral("maps"), written},
         {QStringLiteral("horizontal"), axisJson(result->horizontal, options.method)},
         {QStringLiteral("vertical"), axisJson(result->vertical, options.method)}});
    return kExitOk;
  }
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (maps[i].role == core::TileMapRole::Normal)
      printNote(inputs[int(i)] + QStringLiteral(": blended as a normal map\n"));
  }
  printNote(axisLine("horizontal", result->horizontal, options.method) +
            axisLine("vertical", result->vertical, options.method));
  return kExitOk;
}

}  // namespace relief::cli
