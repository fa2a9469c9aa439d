// ExportCommand; see ExportCommand.h.
#include "ExportCommand.h"

#include "CliCommon.h"
#include "core/exporters/GltfExport.h"
#include "core/exporters/GodotExport.h"
#include "core/exporters/PackageExport.h"
#include "core/material/MaterialPreset.h"

namespace relief::cli {
namespace {

std::optional<core::PackageMapFormat> packageFormat(const QString& name) {
  if (name == QStringLiteral("png"))
    return core::PackageMapFormat::Png8;
  if (name == QStringLiteral("png16"))
    return core::PackageMapFormat::Png16;
  if (name == QStringLiteral("exr"))
    return core::PackageMapFormat::Exr;
  return std::nullopt;
}

}  // namespace

int runExport(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Export a preset's material:\n"
      "  package  a folder with the maps and a preset that points at them\n"
      "  gltf     glTF 2.0 (.gltf, .bin, PNG textures) of the mesh with the material; the\n"
      "           height map and parallax parameters go in the material's extras.relief\n"
      "  godot    a Godot 4 StandardMaterial3D .tres with its heightmap settings\n"
      "See docs/export.md for how parameters convert."));
  const auto option = [&](const QString& name, const QString& help, const QString& value,
                          const QString& fallback = {}) {
    parser.addOption(QCommandLineOption(name, help, value, fallback));
  };
  option(QStringLiteral("preset"), QStringLiteral("The .relief preset to export."),
         QStringLiteral("file"));
  option(QStringLiteral("to"), QStringLiteral("package, gltf or godot."), QStringLiteral("kind"));
  option(QStringLiteral("out"), QStringLiteral("The folder to write (created if needed)."),
         QStringLiteral("folder"));
  option(QStringLiteral("mesh"),
         QStringLiteral("gltf: plane, cube, sphere, cylinder, torus or a mesh file (default: the "
                        "preset's mesh, else plane)."),
         QStringLiteral("name|file"));
  option(QStringLiteral("maps"),
         QStringLiteral("package: data maps as png (8-bit, dithered), png16 or exr (default "
                        "png16); the colour map stays 8-bit sRGB PNG."),
         QStringLiteral("format"), QStringLiteral("png16"));
  option(QStringLiteral("textures"),
         QStringLiteral("package: maps with a compression choice in the preset are also written "
                        "compressed, as ktx2 (default), dds (BC formats; KTX2 for the rest) or "
                        "none."),
         QStringLiteral("container"), QStringLiteral("ktx2"));
  parser.addOption(QCommandLineOption(
      QStringLiteral("strict"),
      QStringLiteral("Fail when the preset has problems (a missing map, a clamped value) "
                     "instead of exporting what loaded.")));
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli export --preset <file> --to "
                                             "<package|gltf|godot> --out <folder>"))) {
    return *exit;
  }
  for (const char* required : {"preset", "to", "out"}) {
    if (!parser.isSet(QString::fromLatin1(required))) {
      printError(QStringLiteral("export needs --%1 (see --help)").arg(QLatin1String(required)));
      return kExitUsage;
    }
  }
  const QString kind = parser.value(QStringLiteral("to"));
  if (kind != QStringLiteral("package") && kind != QStringLiteral("gltf") &&
      kind != QStringLiteral("godot")) {
    printError(QStringLiteral("--to %1: expected package, gltf or godot").arg(kind));
    return kExitUsage;
  }
  const std::optional<core::PackageMapFormat> mapFormat =
      packageFormat(parser.value(QStringLiteral("maps")));
  if (!mapFormat) {
    printError(QStringLiteral("--maps %1: expected png, png16 or exr")
                   .arg(parser.value(QStringLiteral("maps"))));
    return kExitUsage;
  }

  const QString texturesName = parser.value(QStringLiteral("textures"));
  const core::PackageTextures textures =
      texturesName == QStringLiteral("dds")    ? core::PackageTextures::DdsWherePossible
      : texturesName == QStringLiteral("none") ? core::PackageTextures::None
                                               : core::PackageTextures::Ktx2;
  if (texturesName != QStringLiteral("ktx2") && texturesName != QStringLiteral("dds") &&
      texturesName != QStringLiteral("none")) {
    printError(QStringLiteral("--textures %1: expected ktx2, dds or none").arg(texturesName));
    return kExitUsage;
  }

  const QString presetPath = parser.value(QStringLiteral("preset"));
  core::Result<core::LoadedPreset> loaded = core::loadPreset(presetPath.toStdString());
  if (!loaded) {
    printError(QString::fromStdString(loaded.error()));
    return kExitFailure;
  }
  const bool strict = parser.isSet(QStringLiteral("strict"));
  for (const std::string& warning : loaded->warnings) {
    printError((strict ? QString() : QStringLiteral("warning: ")) +
               QString::fromStdString(warning));
  }
  if (strict && !loaded->warnings.empty())
    return kExitFailure;
  const core::Preset& preset = loaded->preset;
  const std::string folder = parser.value(QStringLiteral("out")).toStdString();

  if (kind == QStringLiteral("package")) {
    core::Result<std::string> written = core::exportPackage(preset, folder, {*mapFormat, textures});
    if (!written) {
      printError(QString::fromStdString(written.error()));
      return kExitFailure;
    }
    printOut(QStringLiteral("wrote %1\n").arg(QString::fromStdString(written.value())));
    return kExitOk;
  }
  if (kind == QStringLiteral("gltf")) {
    const QString meshName = parser.isSet(QStringLiteral("mesh"))
                                 ? parser.value(QStringLiteral("mesh"))
                                 : QString::fromStdString(preset.view.mesh);
    core::Mesh mesh;
    if (auto exit = resolveMesh(meshName, mesh))
      return *exit;
    core::Result<std::string> written = core::exportGltf(preset, mesh, folder);
    if (!written) {
      printError(QString::fromStdString(written.error()));
      return kExitFailure;
    }
    printOut(QStringLiteral("wrote %1\n").arg(QString::fromStdString(written.value())));
    return kExitOk;
  }
  core::Result<core::GodotExportResult> written = core::exportGodot(preset, folder);
  if (!written) {
    printError(QString::fromStdString(written.error()));
    return kExitFailure;
  }
  printOut(QStringLiteral("wrote %1\n").arg(QString::fromStdString(written->tresPath)));
  for (const std::string& note : written->notes)
    printOut(QStringLiteral("note: %1\n").arg(QString::fromStdString(note)));
  return kExitOk;
}

}  // namespace relief::cli
