// ExportCommand; see ExportCommand.h. The kinds, the package's choices and the work are core's
// (core/exporters/Exporter.h); this file parses the options and prints what was written.
#include "ExportCommand.h"

#include "app/cli/CliOptionNames.h"

#include "CliCommon.h"
#include "TerminalProgress.h"
#include "core/exporters/Exporter.h"

#include <QJsonArray>

namespace relief::cli {
namespace {

// A table's names joined with '|', for --help and the usage line.
template <class Table>
QString names(const Table& table) {
  return enumNames(std::span(table), [](const auto& entry) { return entry.name; });
}

QString description() {
  QString text = QStringLiteral("Export a preset's material:\n");
  for (const core::ExportKindInfo& kind : core::allExportKinds())
    text += QStringLiteral("  %1 %2\n").arg(qstr(kind.name), -8).arg(qstr(kind.label));
  return text + QStringLiteral("See docs/export.md for how parameters convert.");
}

CliOptions options() {
  return {
      {option::kPreset, QStringLiteral("file"), QStringLiteral("The .relief preset."), {}},
      {option::kTo, QStringLiteral("kind"), names(core::allExportKinds()) + ".", {}},
      {option::kOut,
       QStringLiteral("folder"),
       QStringLiteral("The folder to write (created if needed)."),
       {}},
      {option::kMesh,
       QStringLiteral("name|file"),
       QStringLiteral("gltf: plane, cube, sphere, cylinder, torus or a mesh file (default: the "
                      "preset's mesh, else plane)."),
       {}},
      {option::kMaps, QStringLiteral("format"),
       QStringLiteral("package: data maps as %1; the colour map stays 8-bit sRGB PNG.")
           .arg(names(core::packageMapFormats())),
       qstr(core::packageMapFormats().front().name)},
      {option::kTextures, QStringLiteral("container"),
       QStringLiteral("package: maps with a compression choice in the preset are also written "
                      "compressed: %1 (dds holds the BC formats; KTX2 the rest).")
           .arg(names(core::packageTextureChoices())),
       qstr(core::packageTextureChoices().front().name)},
      strictOption(QStringLiteral("exporting")),
      jsonOption(),
  };
}

// The request from the options and the preset; an exit code when they are wrong.
std::optional<int> buildRequest(const QCommandLineParser& parser, core::ExportRequest& request) {
  const std::optional<core::ExportKind> kind =
      namedOption(parser, option::kTo, core::allExportKinds(),
                  [](const core::ExportKindInfo& info) { return info.kind; });
  const auto mapFormat = namedOption(parser, option::kMaps, core::packageMapFormats());
  const auto textures = namedOption(parser, option::kTextures, core::packageTextureChoices());
  if (!kind || !mapFormat || !textures)
    return kExitUsage;
  request.kind = *kind;
  request.folder = parser.value(option::kOut).toStdString();
  request.package = {*mapFormat, *textures};

  core::Result<core::LoadedPreset> loaded =
      core::loadPreset(parser.value(option::kPreset).toStdString());
  if (!loaded) {
    printError(QString::fromStdString(loaded.error()));
    return kExitFailure;
  }
  if (!acceptPresetProblems(loaded->warnings, parser.isSet(option::kStrict)))
    return kExitFailure;
  request.preset = std::move(loaded->preset);
  if (core::exportKindInfo(request.kind).usesMesh) {
    const bool fromPreset = !parser.isSet(option::kMesh);
    const QString meshName =
        fromPreset ? QString::fromStdString(request.preset.view.mesh) : parser.value(option::kMesh);
    const QString namedBy =
        fromPreset ? parser.value(option::kPreset) + QStringLiteral(": view.mesh") : QString();
    if (auto exit = resolveMesh(meshName, request.mesh, namedBy))
      return *exit;
  }
  return std::nullopt;
}

}  // namespace

int runExport(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(description());
  addOptions(parser, options());
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli export --preset <file> --to <%1> --out "
                                             "<folder>")
                                  .arg(names(core::allExportKinds())))) {
    return *exit;
  }
  if (const QString missing = missingOptions(parser, {option::kPreset, option::kTo, option::kOut});
      !missing.isEmpty()) {
    printError(QStringLiteral("export needs %1 (see --help)").arg(missing));
    return kExitUsage;
  }
  core::ExportRequest request;
  if (auto exit = buildRequest(parser, request))
    return *exit;
  core::Result<core::ExportResult> written = [&] {
    TerminalProgress progress(QStringLiteral("export ") +
                              qstr(core::exportKindInfo(request.kind).name));
    return core::exportMaterial(request, progress.control());
  }();
  if (!written) {
    printError(QString::fromStdString(written.error()));
    return kExitFailure;
  }
  if (parser.isSet(option::kJson)) {
    QJsonArray notes;
    for (const std::string& note : written->notes)
      notes.append(QString::fromStdString(note));
    printJson({{QStringLiteral("kind"), qstr(core::exportKindInfo(request.kind).name)},
               {QStringLiteral("written"), QString::fromStdString(written->writtenPath)},
               {QStringLiteral("notes"), notes}});
    return kExitOk;
  }
  printNote(QStringLiteral("wrote %1\n").arg(QString::fromStdString(written->writtenPath)));
  for (const std::string& note : written->notes)
    printNote(QStringLiteral("note: %1\n").arg(QString::fromStdString(note)));
  return kExitOk;
}

}  // namespace relief::cli
