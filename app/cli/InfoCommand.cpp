// InfoCommand; see InfoCommand.h.
#include "InfoCommand.h"

#include "app/cli/CliOptionNames.h"

#include "CliCommon.h"
#include "MapCheckCommand.h"
#include "core/compression/TextureFile.h"
#include "core/image/ImageIO.h"
#include "core/material/MapSlot.h"

#include <QFileInfo>
#include <QJsonObject>

namespace relief::cli {

namespace {

// A DDS or KTX2 file, read (and checked) by Relief's own texture reader.
int printTextureInfo(const QString& path) {
  core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(path.toStdString());
  if (!texture) {
    printError(QString::fromStdString(texture.error()));
    return kExitFailure;
  }
  const core::TextureFormatInfo& format = core::textureFormatInfo(texture->format);
  printOut(
      QStringLiteral("file: %1\nformat: %2%3\nsize: %4x%5\nmip levels: %6\nbytes: %7\n"
                     "on disk: %8 bytes%9\n")
          .arg(path, qstr(format.label), texture->srgb ? QStringLiteral(" (sRGB)") : QString())
          .arg(texture->levels.front().width)
          .arg(texture->levels.front().height)
          .arg(texture->levels.size())
          .arg(texture->byteSize())
          .arg(QFileInfo(path).size())
          .arg(texture->zstdInFile ? QStringLiteral(" (Zstandard supercompression)") : QString()));
  return kExitOk;
}

// How Relief reads the file in each map slot: colour maps as sRGB colour (the GPU decodes it to
// linear), the others as linear data whatever the file's tag says (Material::setMap retags
// them), so a 16-bit grey PNG tagged sRGB is still read as height values as stored.
QString readAsText(core::MapSlot slot) {
  return core::mapSlotColorSpace(slot) == core::ColorSpace::Srgb
             ? QStringLiteral("sRGB colour")
             : QStringLiteral("linear data, values as stored");
}

}  // namespace

int runInfo(const QStringList& arguments) {
  if (arguments.contains(QStringLiteral("--") + option::kCheck))
    return runMapCheck(arguments);
  QCommandLineParser parser;
  parser.setApplicationDescription(
      QStringLiteral("Print an image's size, channels, bit depth and colour space, after "
                     "checking that all of its pixel data decodes, and how Relief reads it in "
                     "each map slot. With --check, whether a material's normal and height maps "
                     "agree (info --check --help)."));
  parser.addPositionalArgument(QStringLiteral("image"), QStringLiteral("The image file."));
  addOptions(parser, {jsonOption()});
  if (auto exit =
          parseOrExit(parser, arguments, QStringLiteral("relief-cli info <image> [--json]"))) {
    return *exit;
  }
  if (parser.positionalArguments().size() != 1) {
    printError(QStringLiteral("info takes exactly one image (see --help)"));
    return kExitUsage;
  }
  const QString path = parser.positionalArguments().front();
  if (core::containerForPath(path.toStdString()))
    return printTextureInfo(path);
  core::Result<core::ImageFileInfo> info = core::readImageInfo(path.toStdString());
  if (!info) {
    printError(QString::fromStdString(info.error()));
    return kExitFailure;
  }
  if (core::Status intact = core::verifyImageData(path.toStdString()); !intact) {
    printError(QString::fromStdString(intact.error()));
    return kExitFailure;
  }
  const std::optional<core::MapSlot> slotByName =
      core::guessMapSlotFromFileName(QFileInfo(path).fileName().toStdString());
  if (parser.isSet(option::kJson)) {
    QJsonObject readAs;
    for (core::MapSlot slot : core::kAllMapSlots) {
      readAs.insert(qstr(core::mapSlotName(slot)),
                    qstr(core::colorSpaceName(core::mapSlotColorSpace(slot))));
    }
    const QJsonObject object{
        {QStringLiteral("file"), path},
        {QStringLiteral("format"), QString::fromStdString(info->formatName)},
        {QStringLiteral("width"), info->width},
        {QStringLiteral("height"), info->height},
        {QStringLiteral("channels"), info->channels},
        {QStringLiteral("bitsPerChannel"), info->bitsPerChannel},
        {QStringLiteral("float"), info->isFloat},
        {QStringLiteral("fileColorSpace"), qstr(core::colorSpaceName(info->colorSpace))},
        {QStringLiteral("subimages"), info->subimages},
        {QStringLiteral("subimageRead"), QString::fromStdString(info->subimageName)},
        {QStringLiteral("readAs"), readAs},
        {QStringLiteral("slotFromName"),
         slotByName ? QJsonValue(qstr(core::mapSlotName(*slotByName))) : QJsonValue()}};
    printJson(object);
    return kExitOk;
  }
  QString readAs;
  for (core::MapSlot slot : core::kAllMapSlots) {
    readAs +=
        QStringLiteral("\n  as %1: %2%3")
            .arg(qstr(core::mapSlotName(slot)), readAsText(slot),
                 slotByName == slot ? QStringLiteral(" (its name suggests this slot)") : QString());
  }
  printOut(QStringLiteral("file: %1\nformat: %2\nsize: %3x%4\nchannels: %5\n"
                          "bit depth: %6 (%7)\ncolour space in the file: %8\nread by Relief:%9\n")
               .arg(path, QString::fromStdString(info->formatName))
               .arg(info->width)
               .arg(info->height)
               .arg(info->channels)
               .arg(info->bitsPerChannel)
               .arg(info->isFloat ? QStringLiteral("float") : QStringLiteral("integer"))
               .arg(qstr(core::colorSpaceName(info->colorSpace)), readAs));
  if (info->subimages > 1) {
    const QString name = info->subimageName.empty()
                             ? QString()
                             : QStringLiteral(" (\"%1\")").arg(qstr(info->subimageName));
    printOut(QStringLiteral("note: the file holds %1 images (an EXR's parts, a TIFF's pages); "
                            "Relief reads the first%2 alone. Extract another with "
                            "`oiiotool %3 --subimage N -o FILE`.\n")
                 .arg(info->subimages)
                 .arg(name, path));
  }
  return kExitOk;
}

}  // namespace relief::cli
