// PngReader; see PngReader.h. Chunks, filters and the zlib stream as the PNG specification
// (ISO/IEC 15948, third edition) defines them; whole-buffer inflate by libdeflate.
#include "core/image/PngReader.h"

#include "core/base/LargeBuffer.h"
#include "core/base/ParallelFor.h"
#include "core/image/PngFormat.h"

#include <libdeflate.h>

#include <algorithm>
#include <atomic>
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

// The whole file, read at once (LargeBuffer.h: unset until read, in huge pages).
using FileBytes = std::vector<std::uint8_t, LargeBufferAllocator<std::uint8_t>>;

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
Result<std::optional<PngChunks>> walkChunks(const std::string& path, FileBytes& bytes) {
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
Status inflateStream(const std::string& path, const FileBytes& bytes, std::size_t compressed,
                     std::uint8_t* raw, std::size_t inflatedBytes) {
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

// Sample `i` of a row of samples of fewer than 8 bits, packed from the high bits down (section
// 7.2).
int packedSample(const std::uint8_t* row, std::size_t i, int depth) {
  const std::size_t bit = i * std::size_t(depth);
  return (row[bit / 8] >> (8 - depth - int(bit % 8))) & ((1 << depth) - 1);
}

// One unfiltered row's samples as floats; the column of the first palette index past the
// palette's end, if any (-1: none).
int convertRow(const Header& header, const Palette& palette, int channels, const std::uint8_t* row,
               float* target) {
  const int depth = header.bitDepth;
  const std::size_t values = std::size_t(header.width) * std::size_t(channels);
  if (header.colourType == 3) {
    for (std::uint32_t x = 0; x < header.width; ++x) {
      const int index = depth == 8 ? row[x] : packedSample(row, x, depth);
      // An index past the palette's end is an error (section 11.2.3); libpng reads it as black.
      if (index >= palette.entries)
        return int(x);
      for (int c = 0; c < channels; ++c)
        *target++ = float(palette.rgba[index][c]) * (1.0f / 255.0f);
    }
  } else if (depth < 8) {
    // Grey samples scale to 8 bits as libpng expands them (v * 255 / (2^depth - 1)), so the
    // floats match.
    const int greyScale = 255 / ((1 << depth) - 1);
    for (std::size_t i = 0; i < values; ++i)
      target[i] = float(packedSample(row, i, depth) * greyScale) * (1.0f / 255.0f);
  } else if (depth == 16) {
    for (std::size_t i = 0; i < values; ++i)
      target[i] = float(row[2 * i] << 8 | row[2 * i + 1]) * (1.0f / 65535.0f);
  } else {
    for (std::size_t i = 0; i < values; ++i)
      target[i] = float(row[i]) * (1.0f / 255.0f);
  }
  return -1;
}

// Unfilters the inflated rows at `raw` (the tail of the image's own float buffer, see
// decodePngPixels) and converts them to floats in `image`.
//
// Unfiltering is sequential (each row predicts from the one above) and runs first, in place.
// The conversion then runs on the row pool in waves: the rows whose floats end before the first
// raw row not yet converted overwrite nothing still to be read, so they convert in any order.
// For 8-bit RGB a float row is four times its raw row, so the first wave takes three quarters
// of the rows, the next three quarters of the rest, and so on; the last few rows go one by one
// from a copy. On a 2048^2 photograph the conversion (and the first touch of the float
// buffer's pages that it makes) was a serial 100 ms of a 0.45 s `compress --format bc1`.
Status convertRows(const std::string& path, const Header& header, const Palette& palette,
                   int channels, std::uint8_t* raw, std::size_t rowBytes, std::size_t bytesPerPixel,
                   Image& image) {
  const std::size_t rawStride = rowBytes + 1;  // the filter byte, then the row
  for (std::uint32_t y = 0; y < header.height; ++y) {
    std::uint8_t* line = raw + std::size_t(y) * rawStride;
    if (!unfilterRow(line[0], line + 1, y > 0 ? line + 1 - rawStride : nullptr, rowBytes,
                     bytesPerPixel)) {
      return png::damagedPixelData(path, "row " + std::to_string(y) +
                                             " has the unknown filter type " +
                                             std::to_string(int(line[0])));
    }
  }
  const auto badIndex = [&](std::uint32_t y, int x, const std::uint8_t* row) {
    const int index = header.bitDepth == 8 ? row[x] : packedSample(row, x, header.bitDepth);
    return png::damagedPixelData(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                           ") uses palette index " + std::to_string(index) +
                                           "; the palette has " + std::to_string(palette.entries) +
                                           " entries");
  };
  const std::size_t floatStride = sizeof(float) * std::size_t(channels) * header.width;
  const std::size_t rawOffset = std::size_t(raw - reinterpret_cast<std::uint8_t*>(image.data()));
  constexpr std::uint32_t kSmallestWave = 32;
  std::uint32_t done = 0;
  while (done < header.height) {
    const std::uint32_t safe = std::uint32_t(std::min<std::size_t>(
        header.height, (rawOffset + std::size_t(done) * rawStride) / floatStride));
    if (safe < done + kSmallestWave)
      break;
    // The first bad row of the wave, so that the message names the same pixel every run.
    std::atomic<std::uint32_t> firstBad{header.height};
    std::vector<int> badColumn(safe - done, -1);
    parallelFor(int(safe - done), [&](int i) {
      const std::uint32_t y = done + std::uint32_t(i);
      badColumn[i] = convertRow(header, palette, channels, raw + std::size_t(y) * rawStride + 1,
                                image.pixel(0, int(y)));
      if (badColumn[i] >= 0) {
        std::uint32_t seen = firstBad.load();
        while (y < seen && !firstBad.compare_exchange_weak(seen, y)) {
        }
      }
    });
    if (const std::uint32_t y = firstBad.load(); y < header.height)
      return badIndex(y, badColumn[y - done], raw + std::size_t(y) * rawStride + 1);
    done = safe;
  }
  // The rest one by one: row y's floats may cover its own raw bytes (never a later row's), so
  // each is copied out first.
  std::vector<std::uint8_t> row(rowBytes);
  for (std::uint32_t y = done; y < header.height; ++y) {
    std::memcpy(row.data(), raw + std::size_t(y) * rawStride + 1, rowBytes);
    if (const int x = convertRow(header, palette, channels, row.data(), image.pixel(0, int(y)));
        x >= 0)
      return badIndex(y, x, row.data());
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
  FileBytes bytes(static_cast<std::size_t>(size));
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
  // takes fewer bytes than the row it is decoded from plus its filter byte), then the rows are
  // unfiltered where they lie and converted (convertRows). Row y's floats end where row y+1's
  // bytes begin at the latest, so nothing is overwritten before it is read, and no second buffer
  // the size of the image is held beside the map (8192x8192 16-bit grey: 128 MiB less at the
  // peak).
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
