// OpenImageIO-backed image files; see ImageIO.h.
#include "core/image/ImageIO.h"

#include "core/base/InputFile.h"
#include "core/base/Text.h"
#include "core/base/ThirdPartyAllocationScope.h"
#include "core/image/ExrPreflight.h"
#include "core/image/ImageFileTypes.h"
#include "core/image/PngPreflight.h"
#include "core/image/PngReader.h"
#include "core/image/PngWriter.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

namespace relief::core::inline image {
namespace {

namespace fs = std::filesystem;

// OpenImageIO's messages often repeat the path and end with newlines; keep them readable.
std::string cleanOiioMessage(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
    message.pop_back();
  }
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message.empty() ? std::string("unknown error") : message;
}

ColorSpace colorSpaceOf(const OIIO::ImageSpec& spec) {
  if (spec.format.is_floating_point()) {
    return ColorSpace::Linear;
  }
  const std::string tag = spec.get_string_attribute("oiio:ColorSpace");
  return (tag == "sRGB" || tag.rfind("Gamma", 0) == 0) ? ColorSpace::Srgb : ColorSpace::Linear;
}

Status validateSpec(const std::string& path, const OIIO::ImageSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0) {
    return makeError(path + ": the header gives an empty size (" + std::to_string(spec.width) +
                     "x" + std::to_string(spec.height) + ")");
  }
  if (spec.width > kMaxImageDimension || spec.height > kMaxImageDimension) {
    return makeError(path + ": " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                     " exceeds the limit of " + std::to_string(kMaxImageDimension) + "x" +
                     std::to_string(kMaxImageDimension) + " texels");
  }
  if (spec.depth > 1) {
    return makeError(path + ": volume images are not supported");
  }
  if (spec.nchannels < 1) {
    return makeError(path + ": the image has no channels");
  }
  if (spec.nchannels > kMaxImageChannels) {
    return makeError(path + ": " + std::to_string(spec.nchannels) + " channels (the limit is " +
                     std::to_string(kMaxImageChannels) + ")");
  }
  return {};
}

// What a file's first bytes say it is. DDS and KTX2 are Relief's own readers' business
// (core/compression/MapFile.h): OpenImageIO's DDS reader spins forever on uncompressed DDS and
// accepts truncated files, so a DDS renamed to .png is caught here too. For images, the
// OpenImageIO reader named by the signature, or by the extension for formats without one
// (TGA): OpenImageIO's own open() tries every reader it has when the first fails, which took
// up to 13 s on a damaged PNG under the fuzzer and then reported that no reader was found
// instead of what was wrong with the PNG.
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

Result<std::unique_ptr<OIIO::ImageInput>> openInput(const std::string& path) {
  // OpenImageIO reports a missing file, a folder or an empty file vaguely, and would block on
  // a FIFO: the input policy comes first.
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
  // Header checks before a library allocates what a damaged header claims.
  if (sniffed.reader == "openexr") {
    if (Status header = preflightExr(path, readable.value()); !header)
      return makeError(header.error());
  }
  if (sniffed.reader == "png") {
    if (Status chunks = preflightPng(path, readable.value()); !chunks)
      return makeError(chunks.error());
  }
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(sniffed.reader);
  if (!input) {
    return makeError(path + ": not an image file Relief reads (" +
                     cleanOiioMessage(OIIO::geterror()) + ")");
  }
  bool opened = false;
  {
    const ThirdPartyAllocationScope oiioMayLeakOnDamagedHeaders;
    // Maps keep their alpha as stored: it is data (a packed height, a mask), not coverage to
    // premultiply by, and PNG stores it straight. Without this hint OpenImageIO multiplies the
    // colour of PNG, TGA and unassociated-alpha TIFF files by their alpha on reading.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::ImageSpec spec;
    opened = input->open(path, spec, config);
  }
  if (!opened) {
    return makeError(path + ": cannot read as an image (" + cleanOiioMessage(input->geterror()) +
                     ")");
  }
  if (Status valid = validateSpec(path, input->spec()); !valid) {
    return makeError(valid.error());
  }
  return input;
}

// Runs one pixel read and turns a failure, or a failure reported late on close (a CRC error in
// the last chunk), into a message naming the file.
template <class Read>
Status readPixels(OIIO::ImageInput& input, const std::string& path, Read read, bool closeAfter) {
  bool ok = false;
  {
    const ThirdPartyAllocationScope oiioMayLeakOnDamagedFiles;
    ok = read();
  }
  if (ok && closeAfter)
    ok = input.close() && !input.has_error();
  if (!ok) {
    return makeError(path + ": the pixel data is damaged or truncated (" +
                     cleanOiioMessage(input.geterror()) + ")");
  }
  return {};
}

OIIO::TypeDesc chooseFileType(const Image& image, const std::string& path, SampleFormat format) {
  const ImageFileType* type = imageFileTypeForPath(path);
  const bool isExr = type && type->isFloat;
  const bool supports16 = type && type->maxBitsPerChannel == 16;
  switch (format) {
    case SampleFormat::UInt8:
      return OIIO::TypeDesc::UINT8;
    case SampleFormat::UInt16:
      return OIIO::TypeDesc::UINT16;
    case SampleFormat::Half:
      return OIIO::TypeDesc::HALF;
    case SampleFormat::Float:
      return OIIO::TypeDesc::FLOAT;
    case SampleFormat::Auto:
      break;
  }
  if (isExr) {
    return image.sourceBitsPerChannel() == 32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF;
  }
  if (supports16 && image.sourceBitsPerChannel() > 8) {
    return OIIO::TypeDesc::UINT16;
  }
  return OIIO::TypeDesc::UINT8;
}

}  // namespace

Result<ImageFileInfo> readImageInfo(const std::string& path) {
  auto input = openInput(path);
  if (!input) {
    return makeError(input.error());
  }
  const OIIO::ImageSpec& spec = input.value()->spec();
  ImageFileInfo info;
  info.width = spec.width;
  info.height = spec.height;
  info.channels = spec.nchannels;
  info.bitsPerChannel = spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size() * 8));
  info.isFloat = spec.format.is_floating_point();
  info.formatName = input.value()->format_name();
  info.colorSpace = colorSpaceOf(spec);
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
  auto opened = openInput(path);
  if (!opened)
    return makeError(opened.error());
  OIIO::ImageInput& input = *opened.value();
  const OIIO::ImageSpec& spec = input.spec();
  // Tiled files (VFX pipelines' TIFFs and mip-mapped EXRs) are read a row of tiles at a time:
  // OpenImageIO 2.4's read_scanlines divides by zero on them (SIGFPE). Strips stay aligned to
  // the tile height; the last one ends at the image's edge.
  const bool tiled = spec.tile_width > 0 && spec.tile_height > 0;
  const int stripRows = tiled ? spec.tile_height * std::max(1, 64 / spec.tile_height) : 64;
  const int stripWidth =
      tiled ? (spec.width + spec.tile_width - 1) / spec.tile_width * spec.tile_width : spec.width;
  std::vector<float> strip(std::size_t(stripWidth) * std::size_t(spec.nchannels) *
                           std::size_t(stripRows));
  const int lastRow = spec.y + spec.height;
  for (int y = spec.y; y < lastRow; y += stripRows) {
    const int end = std::min(y + stripRows, lastRow);
    const auto readStrip = [&] {
      if (tiled) {
        return input.read_tiles(0, 0, spec.x, spec.x + spec.width, y, end, spec.z,
                                spec.z + std::max(1, spec.depth), 0, spec.nchannels,
                                OIIO::TypeDesc::FLOAT, strip.data());
      }
      return input.read_scanlines(0, 0, y, end, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                                  strip.data());
    };
    if (Status status = readPixels(input, path, readStrip, end == lastRow); !status) {
      return status;
    }
  }
  return {};
}

Result<Image> loadImage(const std::string& path) {
  auto opened = openInput(path);
  if (!opened) {
    return makeError(opened.error());
  }
  OIIO::ImageInput& input = *opened.value();
  const OIIO::ImageSpec& spec = input.spec();
  const int channels = std::min(spec.nchannels, 4);

  Image image(spec.width, spec.height, channels, colorSpaceOf(spec));
  image.setSourceBitsPerChannel(
      spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size() * 8)));
  if (std::string_view(input.format_name()) == "png" && channels == spec.nchannels) {
    // OpenImageIO has read the header and colour space; the pixels of common PNGs decode
    // faster in Relief's own reader (PngReader.h), which hands the rest back.
    const Result<PngFastDecode> fast = decodePngPixels(path, image);
    if (!fast)
      return makeError(fast.error());
    if (fast.value() == PngFastDecode::Decoded)
      return image;
  }
  const auto readAll = [&] {
    return input.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, image.data());
  };
  if (Status status = readPixels(input, path, readAll, true); !status) {
    return makeError(status.error());
  }
  return image;
}

namespace {

// Every type but PNG goes through OpenImageIO, into `temporary`.
Status writeWithOpenImageIO(const Image& image, const std::string& path,
                            const std::string& temporary, OIIO::TypeDesc sampleType) {
  auto output = OIIO::ImageOutput::create(path);
  if (!output) {
    return makeError(path + ": cannot write this file type (" + cleanOiioMessage(OIIO::geterror()) +
                     ")");
  }
  OIIO::ImageSpec spec(image.width(), image.height(), image.channels(), sampleType);
  // Tag linear data (normals, heights) as such, so readers do not treat it as sRGB colour.
  spec.attribute("oiio:ColorSpace", image.colorSpace() == ColorSpace::Srgb ? "sRGB" : "Linear");
  // Alpha is data and is written as it is (OpenImageIO would otherwise divide the colour by it
  // for formats that store straight alpha, losing whatever exceeds the alpha).
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (const ImageFileType* type = imageFileTypeForPath(path); type && type->isFloat) {
    spec.attribute("compression", "zip");
  }
  // Quantising finer data to 8 bits bands smooth gradients; OpenImageIO's dither adds noise of
  // under half a level first. Images that came from 8-bit files stay exact.
  if (spec.format == OIIO::TypeDesc::UINT8 && image.sourceBitsPerChannel() != 8) {
    spec.attribute("oiio:dither", 1);
  }
  const bool written = output->open(temporary, spec) &&
                       output->write_image(OIIO::TypeDesc::FLOAT, image.data()) && output->close();
  if (!written)
    return makeError(path + ": cannot write (" + cleanOiioMessage(output->geterror()) + ")");
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
  const OIIO::TypeDesc sampleType = chooseFileType(image, path, format);
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
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
  Status written;
  if (type && type->extension == "png") {
    // PNG: our writer (PngWriter.h: twenty times faster, and it checks its own writes, so the
    // file needs no second decoding). PNG holds 8 or 16 bits; float requests get 16.
    PngWriteOptions options;
    options.bitsPerChannel = sampleType == OIIO::TypeDesc::UINT8 ? 8 : 16;
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
