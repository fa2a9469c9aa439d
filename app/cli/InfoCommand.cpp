// InfoCommand; see InfoCommand.h.
#include "InfoCommand.h"

#include "CliCommon.h"
#include "core/compression/TextureFile.h"
#include "core/image/ImageIO.h"

#include <QFileInfo>

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

}  // namespace

int runInfo(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      QStringLiteral("Print an image's size, channels, bit depth and colour space, after "
                     "checking that all of its pixel data decodes."));
  parser.addPositionalArgument(QStringLiteral("image"), QStringLiteral("The image file."));
  if (auto exit = parseOrExit(parser, arguments, QStringLiteral("relief-cli info <image>"))) {
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
  printOut(QStringLiteral("file: %1\nformat: %2\nsize: %3x%4\nchannels: %5\n"
                          "bit depth: %6 (%7)\ncolour space: %8\n")
               .arg(path, QString::fromStdString(info->formatName))
               .arg(info->width)
               .arg(info->height)
               .arg(info->channels)
               .arg(info->bitsPerChannel)
               .arg(info->isFloat ? QStringLiteral("float") : QStringLiteral("integer"))
               .arg(qstr(core::colorSpaceName(info->colorSpace))));
  return kExitOk;
}

}  // namespace relief::cli
