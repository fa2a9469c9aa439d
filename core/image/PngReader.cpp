// PngReader; see PngReader.h. Chunks, filters and the zlib stream as the PNG specification
// (ISO/IEC 15948, third edition) defines them; whole-buffer inflate by libdeflate.
#include "core/image/PngReader.h"

#include "core/image/PngFormat.h"

#include <libdeflate.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

namespace relief::core::inline image {
namespace {

using png::allowedDepth;
using png::bigEndian32;
using png::kSignature;
using png::storedSamplesOf;
using png::unfilterRow;

struct Header {
  std::uint32_t width = 0, height = 0;
  int bitDepth = 0, colourType = 0, interlace = 0;
};

// The palette and its alphas (PLTE, tRNS), as 8-bit RGBA entries.
struct Palette {
  int entries = 0;
  bool hasAlpha = false;
  std::uint8_t rgba[256][4] = {};
};

// What the chunk walk found: the header, the palette and its alphas, and how many bytes of IDAT
// payload now lie together at the front of the file's buffer.
struct PngChunks {
  Header header;
  Palette palette;
  bool sawHeader = false;
  std::size_t compressed = 0;
};

// Walks the chunks, checking the CRC of every critical one; the IDAT payloads are moved together
// to the front of `bytes` (the file's own buffer, so no second copy of the compressed stream).
// Empty when the file holds something this reader leaves to OpenImageIO.
Result<std::optional<PngChunks>> walkChunks(const std::string& path,
                                            std::vector<std::uint8_t>& bytes) {
  PngChunks chunks;
  Header& header = chunks.header;
  Palette& palette = chunks.palette;
  bool sawEnd = false;
  std::size_t at = sizeof kSignature;
  while (at + 12 <= bytes.size() && !sawEnd) {
    const std::uint32_t length = bigEndian32(&bytes[at]);
    if (length > 0x7fffffffu || std::size_t(length) + 12 > bytes.size() - at)
      return png::damagedPixelData(path, "a chunk runs past the end of the file");
    const std::uint8_t* type = &bytes[at + 4];
    const std::uint8_t* data = type + 4;
    const std::uint32_t storedCrc = bigEndian32(data + length);
    const bool critical = (type[0] & 0x20) == 0;  // upper-case first letter
    if (critical && libdeflate_crc32(0, type, length + 4) != storedCrc) {
      return png::damagedPixelData(path, "the CRC of chunk \"" + std::string(type, type + 4) +
                                             "\" at byte " + std::to_string(at) +
                                             " does not match");
    }
    if (std::memcmp(type, "IHDR", 4) == 0) {
      if (length != 13)
        return png::damagedPixelData(path, "the IHDR chunk is not 13 bytes");
      header.width = bigEndian32(data);
      header.height = bigEndian32(data + 4);
      header.bitDepth = data[8];
      header.colourType = data[9];
      header.interlace = data[12];
      chunks.sawHeader = true;
    } else if (std::memcmp(type, "IDAT", 4) == 0) {
      // Never overlaps forward: compressed < at.
      std::memmove(&bytes[chunks.compressed], data, length);
      chunks.compressed += length;
    } else if (std::memcmp(type, "PLTE", 4) == 0) {
      if (length % 3 != 0 || length / 3 > 256 || length == 0)
        return png::damagedPixelData(path,
                                     "the palette (PLTE) has " + std::to_string(length) + " bytes");
      palette.entries = int(length / 3);
      for (int i = 0; i < palette.entries; ++i) {
        std::memcpy(palette.rgba[i], data + 3 * i, 3);
        palette.rgba[i][3] = 255;
      }
    } else if (std::memcmp(type, "tRNS", 4) == 0) {
      if (header.colourType != 3)
        return std::optional<PngChunks>();  // colour-key transparency of grey or RGB: OpenImageIO's
      if (length > std::uint32_t(palette.entries))
        return png::damagedPixelData(
            path, "the transparency chunk (tRNS) has more entries than the palette");
      for (std::uint32_t i = 0; i < length; ++i)
        palette.rgba[i][3] = data[i];
      palette.hasAlpha = true;
    } else if (std::memcmp(type, "IEND", 4) == 0) {
      sawEnd = true;
    }
    at += std::size_t(length) + 12;
  }
  return std::optional<PngChunks>(chunks);
}

// Inflates the zlib stream (the first `compressed` bytes of `bytes`) into exactly
// `inflatedBytes` at `raw`.
Status inflateStream(const std::string& path, const std::vector<std::uint8_t>& bytes,
                     std::size_t compressed, std::uint8_t* raw, std::size_t inflatedBytes) {
  const std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> inflater(
      libdeflate_alloc_decompressor(), libdeflate_free_decompressor);
  if (!inflater)
    return makeError(path + ": not enough memory to decode");
  // With no "actual size" out-parameter libdeflate demands exactly `inflatedBytes`: a short or
  // long stream fails like a corrupt one. It checks the Adler-32 too.
  const libdeflate_result result = libdeflate_zlib_decompress(
      inflater.get(), bytes.data(), compressed, raw, inflatedBytes, nullptr);
  if (result != LIBDEFLATE_SUCCESS) {
    return png::damagedPixelData(path, result == LIBDEFLATE_SHORT_OUTPUT
                                           ? "the zlib stream ends early"
                                       : result == LIBDEFLATE_INSUFFICIENT_SPACE
                                           ? "the zlib stream holds more than the image"
                                           : "the zlib stream is corrupt");
  }
  return {};
}

// Unfilters the inflated rows at `raw` and converts them to floats in `image`, top down.
Status convertRows(const std::string& path, const Header& header, const Palette& palette,
                   int channels, const std::uint8_t* raw, std::size_t rowBytes,
                   std::size_t bytesPerPixel, Image& image) {
  const bool indexed = header.colourType == 3;
  // Samples of fewer than 8 bits are packed from the high bits down (section 7.2); grey ones
  // scale to 8 bits as libpng expands them (v * 255 / (2^depth - 1)), so the floats match.
  const int depth = header.bitDepth;
  const auto packedSample = [depth](const std::uint8_t* source, std::size_t i) {
    const std::size_t bit = i * std::size_t(depth);
    return (source[bit / 8] >> (8 - depth - int(bit % 8))) & ((1 << depth) - 1);
  };
  const std::size_t values = std::size_t(header.width) * std::size_t(channels);
  const int greyScale = depth < 8 ? 255 / ((1 << depth) - 1) : 1;
  // Each row is copied out before its floats overwrite it; the unfiltered row above is kept for
  // the next row's filter. Sequential, as unfiltering is (each row predicts from the one above).
  std::vector<std::uint8_t> rows(2 * rowBytes);
  std::uint8_t* row = rows.data();
  std::uint8_t* above = nullptr;
  for (std::uint32_t y = 0; y < header.height; ++y) {
    const std::uint8_t* line = raw + std::size_t(y) * (rowBytes + 1);
    const std::uint8_t filter = line[0];
    std::memcpy(row, line + 1, rowBytes);
    if (!unfilterRow(filter, row, above, rowBytes, bytesPerPixel)) {
      return png::damagedPixelData(path, "row " + std::to_string(y) +
                                             " has the unknown filter type " +
                                             std::to_string(int(filter)));
    }
    float* target = image.pixel(0, int(y));
    if (indexed) {
      for (std::uint32_t x = 0; x < header.width; ++x) {
        const int index = depth == 8 ? row[x] : packedSample(row, x);
        // An index past the palette's end is an error (section 11.2.3); libpng reads it as black.
        if (index >= palette.entries) {
          return png::damagedPixelData(path, "pixel (" + std::to_string(x) + ", " +
                                                 std::to_string(y) + ") uses palette index " +
                                                 std::to_string(index) + "; the palette has " +
                                                 std::to_string(palette.entries) + " entries");
        }
        for (int c = 0; c < channels; ++c)
          *target++ = float(palette.rgba[index][c]) * (1.0f / 255.0f);
      }
    } else if (depth < 8) {
      for (std::size_t i = 0; i < values; ++i)
        target[i] = float(packedSample(row, i) * greyScale) * (1.0f / 255.0f);
    } else if (depth == 16) {
      for (std::size_t i = 0; i < values; ++i)
        target[i] = float(row[2 * i] << 8 | row[2 * i + 1]) * (1.0f / 65535.0f);
    } else {
      for (std::size_t i = 0; i < values; ++i)
        target[i] = float(row[i]) * (1.0f / 255.0f);
    }
    above = row;
    row = row == rows.data() ? rows.data() + rowBytes : rows.data();
  }
  return {};
}

}  // namespace

Result<PngFastDecode> decodePngPixels(const std::string& path, Image& image) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file)
    return makeError(path + ": cannot be opened for reading");
  const std::streamoff size = file.tellg();
  if (size < std::streamoff(sizeof kSignature))
    return PngFastDecode::NotHandled;
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  file.seekg(0);
  if (!file.read(reinterpret_cast<char*>(bytes.data()), size))
    return makeError(path + ": cannot be read");
  if (std::memcmp(bytes.data(), kSignature, sizeof kSignature) != 0)
    return PngFastDecode::NotHandled;

  Result<std::optional<PngChunks>> walked = walkChunks(path, bytes);
  if (!walked)
    return makeError(walked.error());
  if (!walked.value())
    return PngFastDecode::NotHandled;
  const Header& header = walked.value()->header;
  const Palette& palette = walked.value()->palette;
  const bool sawHeader = walked.value()->sawHeader;
  const std::size_t compressed = walked.value()->compressed;
  const int samples = storedSamplesOf(header.colourType);
  if (!sawHeader || samples == 0 || header.interlace != 0 ||
      !allowedDepth(header.colourType, header.bitDepth))
    return PngFastDecode::NotHandled;
  const bool indexed = header.colourType == 3;
  if (indexed && palette.entries == 0)
    return png::damagedPixelData(path, "a palette image without a palette (PLTE)");
  // Palette images expand to RGB, or RGBA when tRNS gives alphas, as libpng expands them.
  const int channels = indexed ? (palette.hasAlpha ? 4 : 3) : samples;
  if (header.width != std::uint32_t(image.width()) ||
      header.height != std::uint32_t(image.height()) || channels != image.channels())
    return PngFastDecode::NotHandled;  // OpenImageIO saw something else; trust its reading

  const std::size_t bitsPerPixel = std::size_t(header.bitDepth) * std::size_t(samples);
  const std::size_t bytesPerPixel = std::max<std::size_t>(1, bitsPerPixel / 8);  // for filters
  const std::size_t rowBytes = (bitsPerPixel * header.width + 7) / 8;
  const std::size_t inflatedBytes = (rowBytes + 1) * header.height;
  if (compressed == 0)
    return png::damagedPixelData(path, "no IDAT chunk");

  // The stream is inflated into the tail of the image's own float buffer (a row of floats never
  // takes fewer bytes than the row it is decoded from plus its filter byte), then each row is
  // unfiltered and converted from the top down. Row y's floats end where row y+1's bytes begin
  // at the latest, so nothing is overwritten before it is read, and no second buffer the size
  // of the image is held beside the map (8192x8192 16-bit grey: 128 MiB less at the peak).
  auto* const floatBytes = reinterpret_cast<std::uint8_t*>(image.data());
  const std::size_t floatRowBytes = sizeof(float) * std::size_t(channels) * header.width;
  std::uint8_t* const raw = floatBytes + floatRowBytes * header.height - inflatedBytes;
  if (Status inflated = inflateStream(path, bytes, compressed, raw, inflatedBytes); !inflated)
    return makeError(inflated.error());
  bytes = {};
  if (Status converted =
          convertRows(path, header, palette, channels, raw, rowBytes, bytesPerPixel, image);
      !converted)
    return makeError(converted.error());
  return PngFastDecode::Decoded;
}

}  // namespace relief::core::inline image
