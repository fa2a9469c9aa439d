// Image files; see ImageIO.h. PNG is read and written by Relief's own code (PngPreflight,
// PngReader, PngVerify, PngWriter); every other type, and the PNG features PngReader leaves,
// through OpenImageIO in its module (OiioModule.h), loaded the first time a file needs it.
#include "core/image/ImageIO.h"

#include "core/base/InputFile.h"
#include "core/base/TemporaryFiles.h"
#include "core/base/Text.h"
#include "core/image/ExrPreflight.h"
#include "core/image/ImageFileTypes.h"
#include "core/image/OiioModule.h"
#include "core/image/PngPreflight.h"
#include "core/image/PngReader.h"
#include "core/image/PngVerify.h"
#include "core/image/PngWriter.h"
#include "core/image/TiffPreflight.h"

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>

namespace relief::core::inline image {
namespace {

namespace fs = std::filesystem;

Status validateSize(const std::string& path, std::int64_t width, std::int64_t height, int depth,
                    int channels) {
  if (width <= 0 || height <= 0) {
    return makeError(path + ": the header gives an empty size (" + std::to_string(width) + "x" +
                     std::to_string(height) + ")");
  }
  if (width > kMaxImageDimension || height > kMaxImageDimension) {
    return makeError(path + ": " + std::to_string(width) + "x" + std::to_string(height) +
                     " exceeds the limit of " + std::to_string(kMaxImageDimension) + "x" +
                     std::to_string(kMaxImageDimension) + " texels");
  }
  if (depth > 1) {
    return makeError(path + ": volume images are not supported");
  }
  if (channels < 1) {
    return makeError(path + ": the image has no channels");
  }
  if (channels > kMaxImageChannels) {
    return makeError(path + ": " + std::to_string(channels) + " channels (the limit is " +
                     std::to_string(kMaxImageChannels) + ")");
  }
  return {};
}

// What a file's first bytes say it is. DDS and KTX2 are Relief's own readers' business
// (core/compression/MapFile.h): OpenImageIO's DDS reader spins forever on uncompressed DDS and
// accepts truncated files, so a DDS renamed to .png is caught here too. For images, the reader
// named by the signature, or by the extension for formats without one (TGA): OpenImageIO's own
// open() tries every reader it has when the first fails, which took up to 13 s on a damaged PNG
// under the fuzzer and then reported that no reader was found instead of what was wrong.
struct Sniffed {
  bool textureContainer = false;
  std::string reader;  // an OpenImageIO format name or extension
};

Sniffed sniff(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  char magic[12] = {};
  file.read(magic, sizeof magic);
  static const char kKtx2[12] = {'\xAB', 'K',    'T',  'X',  ' ',    '2',
                                 '0',    '\xBB', '\r', '\n', '\x1A', '\n'};
  if (std::memcmp(magic, "DDS ", 4) == 0 || std::memcmp(magic, kKtx2, sizeof kKtx2) == 0)
    return {true, {}};
  struct Signature {
    const char* bytes;
    std::size_t size;
    const char* reader;
  };
  static constexpr Signature kSignatures[] = {
      {"\x89PNG", 4, "png"},     {"II*\0", 4, "tiff"},        {"MM\0*", 4, "tiff"},
      {"v/1\x01", 4, "openexr"}, {"\xFF\xD8\xFF", 3, "jpeg"}, {"#?", 2, "hdr"},
  };
  for (const Signature& signature : kSignatures) {
    if (std::memcmp(magic, signature.bytes, signature.size) == 0)
      return {false, signature.reader};
  }
  return {false, lowerExtension(path)};
}

// An image file that passed the input policy and the checks of its header that come before
// any library reads it. PNGs carry the header Relief read.
struct CheckedFile {
  std::string reader;
  std::optional<PngHeader> png;
};

Result<CheckedFile> checkImageFile(const std::string& path) {
  // Libraries report a missing file, a folder or an empty file vaguely, and would block on a
  // FIFO: the input policy comes first.
  const Result<std::uintmax_t> readable = checkInputFile(path, kMaxImageFileBytes, "image file");
  if (!readable) {
    return makeError(readable.error());
  }
  const Sniffed sniffed = sniff(path);
  if (sniffed.textureContainer) {
    return makeError(path +
                     ": a compressed texture (DDS or KTX2), not an image file; it is read "
                     "by Relief's texture reader (relief-cli decode, or as a map)");
  }
  CheckedFile checked{sniffed.reader, std::nullopt};
  // Header checks before a library allocates what a damaged header claims.
  if (sniffed.reader == "openexr") {
    if (Status header = preflightExr(path, readable.value()); !header)
      return makeError(header.error());
  }
  if (sniffed.reader == "tiff") {
    if (Status directory = preflightTiff(path); !directory)
      return makeError(directory.error());
  }
  if (sniffed.reader == "png") {
    Result<PngHeader> header = preflightPng(path, readable.value());
    if (!header)
      return makeError(header.error());
    if (Status size = validateSize(path, header->width, header->height, 1, header->channels());
        !size)
      return makeError(size.error());
    checked.png = header.value();
  }
  return checked;
}

Result<std::unique_ptr<OiioInput>> openWithOpenImageIO(const std::string& path,
                                                       const std::string& reader) {
  const Result<OiioModule*> module = oiioModule(path + ": reading this file type");
  if (!module)
    return makeError(module.error());
  Result<std::unique_ptr<OiioInput>> input = module.value()->open(path, reader);
  if (!input)
    return input;
  const OiioHeader& header = input.value()->header();
  if (Status valid = validateSize(path, header.width, header.height, header.depth, header.channels);
      !valid) {
    return makeError(valid.error());
  }
  return input;
}

ColorSpace colorSpaceOf(const OiioHeader& header) {
  return header.isFloat ? ColorSpace::Linear : colorSpaceFromOiioName(header.colorSpaceName);
}

OiioSampleType chooseSampleType(const Image& image, const std::string& path, SampleFormat format) {
  const ImageFileType* type = imageFileTypeForPath(path);
  const bool isExr = type && type->isFloat;
  const bool supports16 = type && type->maxBitsPerChannel == 16;
  switch (format) {
    case SampleFormat::UInt8:
      return OiioSampleType::UInt8;
    case SampleFormat::UInt16:
      return OiioSampleType::UInt16;
    case SampleFormat::Half:
      return OiioSampleType::Half;
    case SampleFormat::Float:
      return OiioSampleType::Float;
    case SampleFormat::Auto:
      break;
  }
  if (isExr) {
    return image.sourceBitsPerChannel() == 32 ? OiioSampleType::Float : OiioSampleType::Half;
  }
  if (supports16 && image.sourceBitsPerChannel() > 8) {
    return OiioSampleType::UInt16;
  }
  return OiioSampleType::UInt8;
}

}  // namespace

Result<ImageFileInfo> readImageInfo(const std::string& path) {
  const Result<CheckedFile> checked = checkImageFile(path);
  if (!checked)
    return makeError(checked.error());
  ImageFileInfo info;
  if (const std::optional<PngHeader>& png = checked->png) {
    info.width = int(png->width);
    info.height = int(png->height);
    info.channels = png->channels();
    info.bitsPerChannel = png->bitsPerChannel();
    info.formatName = "png";
    info.colorSpace = png->colorSpace;
    return info;
  }
  const auto input = openWithOpenImageIO(path, checked->reader);
  if (!input)
    return makeError(input.error());
  const OiioHeader& header = input.value()->header();
  info.width = header.width;
  info.height = header.height;
  info.channels = header.channels;
  info.bitsPerChannel = header.bitsPerSample;
  info.isFloat = header.isFloat;
  info.formatName = header.formatName;
  info.colorSpace = colorSpaceOf(header);
  info.subimages = header.subimages;
  info.subimageName = header.subimageName;
  return info;
}

SampleFormat fullPrecisionFormatFor(const std::string& path) {
  const ImageFileType* type = imageFileTypeForPath(path);
  if (type && type->isFloat)
    return SampleFormat::Float;
  if (type && type->maxBitsPerChannel == 16)
    return SampleFormat::UInt16;
  return SampleFormat::UInt8;
}

Status verifyImageData(const std::string& path) {
  const Result<CheckedFile> checked = checkImageFile(path);
  if (!checked)
    return makeError(checked.error());
  if (checked->png)
    return verifyPngData(path, *checked->png);
  const auto input = openWithOpenImageIO(path, checked->reader);
  if (!input)
    return makeError(input.error());
  return input.value()->verify();
}

Result<Image> loadImage(const std::string& path) {
  const Result<CheckedFile> checked = checkImageFile(path);
  if (!checked)
    return makeError(checked.error());
  if (const std::optional<PngHeader>& png = checked->png) {
    Image image =
        Image::forOverwrite(int(png->width), int(png->height), png->channels(), png->colorSpace);
    image.setSourceBitsPerChannel(png->bitsPerChannel());
    const Result<PngFastDecode> decoded = decodePngPixels(path, image);
    if (!decoded)
      return makeError(decoded.error());
    if (decoded.value() == PngFastDecode::Decoded)
      return image;
  }
  const auto opened = openWithOpenImageIO(path, checked->reader);
  if (!opened)
    return makeError(opened.error());
  OiioInput& input = *opened.value();
  const OiioHeader& header = input.header();
  const int channels = std::min(header.channels, 4);
  Image image(header.width, header.height, channels, colorSpaceOf(header));
  image.setSourceBitsPerChannel(header.bitsPerSample);
  if (Status status = input.readImage(channels, image.data()); !status)
    return makeError(status.error());
  return image;
}

namespace {

// Every type but PNG goes through OpenImageIO, into `temporary`.
Status writeWithOpenImageIO(const Image& image, const std::string& path,
                            const std::string& temporary, OiioSampleType sampleType) {
  const Result<OiioModule*> module = oiioModule(path + ": writing this file type");
  if (!module)
    return makeError(module.error());
  OiioWriteRequest request;
  request.pixels = image.data();
  request.width = image.width();
  request.height = image.height();
  request.channels = image.channels();
  request.sampleType = sampleType;
  request.srgb = image.colorSpace() == ColorSpace::Srgb;
  const ImageFileType* type = imageFileTypeForPath(path);
  request.zip = type && type->isFloat;
  // Images that came from 8-bit files stay exact; finer data is dithered to 8 bits.
  request.dither = sampleType == OiioSampleType::UInt8 && image.sourceBitsPerChannel() != 8;
  if (Status written = module.value()->write(path, temporary, request); !written)
    return written;
  // Some of OpenImageIO's writers report success after a short write, on a full disk or past a
  // file-size limit. Decoding the file before it replaces the old one catches that.
  if (Status intact = verifyImageData(temporary); !intact) {
    return makeError(path +
                     ": cannot write (the written file does not read back whole: the "
                     "disk may be full)");
  }
  return {};
}

}  // namespace

Status saveImage(const Image& image, const std::string& path, SampleFormat format) {
  if (image.isEmpty()) {
    return makeError(path + ": nothing to save (the image is empty)");
  }
  const OiioSampleType sampleType = chooseSampleType(image, path, format);
  const ImageFileType* type = imageFileTypeForPath(path);
  // The temporary keeps the extension so that OpenImageIO's writer sees the same format.
  const fs::path target(path);
  const fs::path temporary = target.parent_path() / ("." + target.stem().string() + ".saving" +
                                                     target.extension().string());
  {
    std::error_code ignored;
    if (fs::is_directory(target, ignored))
      return makeError(path + ": is a folder, not a file that can be replaced");
  }
  // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, which would kill the process
  // and leave the temporary file; ignored, the write fails instead and is cleaned up below.
  const TemporaryFile removedIfInterrupted(temporary.string());
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
  Status written;
  if (type && type->extension == "png") {
    // PNG: our writer (PngWriter.h: twenty times faster, and it checks its own writes, so the
    // file needs no second decoding). PNG holds 8 or 16 bits; float requests get 16.
    PngWriteOptions options;
    options.bitsPerChannel = sampleType == OiioSampleType::UInt8 ? 8 : 16;
    options.dither = options.bitsPerChannel == 8 && image.sourceBitsPerChannel() != 8;
    written = writePng(image, temporary.string(), options);
    if (!written) {
      // Name the file the caller asked for, not the temporary.
      std::string message = written.error();
      if (message.rfind(temporary.string(), 0) == 0)
        message = path + message.substr(temporary.string().size());
      written = makeError(message);
    }
  } else {
    written = writeWithOpenImageIO(image, path, temporary.string(), sampleType);
  }
  std::signal(SIGXFSZ, previousHandler);
  if (!written) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return written;
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    std::error_code ignored;  // the rename's error is the one to report
    fs::remove(temporary, ignored);
    return makeError(path + ": cannot replace the file (" + ec.message() + ")");
  }
  return {};
}

}  // namespace relief::core::inline image
