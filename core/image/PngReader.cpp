// PngReader; see PngReader.h. Chunks, filters and the zlib stream as the PNG specification
// (ISO/IEC 15948, third edition) defines them; whole-buffer inflate by libdeflate.
#include "core/image/PngReader.h"

#include "core/base/ParallelFor.h"

#include <libdeflate.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <vector>

namespace relief::core::inline image {
namespace {

constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// Above this many inflated bytes the whole-image buffer would cost more memory than speed is
// worth; OpenImageIO's reader streams scanlines instead.
constexpr std::size_t kMaxInflatedBytes = std::size_t(1) << 30;

// Rows are converted to floats in blocks of this many, in parallel, once all are unfiltered.
constexpr int kRowsPerBlock = 64;

std::uint32_t bigEndian32(const std::uint8_t* bytes) {
  return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 |
         std::uint32_t(bytes[2]) << 8 | std::uint32_t(bytes[3]);
}

struct Header {
  std::uint32_t width = 0, height = 0;
  int bitDepth = 0, colourType = 0, interlace = 0;
};

int channelsOf(int colourType) {
  switch (colourType) {
    case 0:
      return 1;  // grey
    case 4:
      return 2;  // grey and alpha
    case 2:
      return 3;  // RGB
    case 6:
      return 4;  // RGBA
    default:
      return 0;  // palette (3) and reserved types: OpenImageIO's
  }
}

// Undoes one row's filter in place (PNG section 9.2). `above` is the previous unfiltered row, or
// null for the first row, whose "above" bytes are zero.
bool unfilterRow(std::uint8_t filter, std::uint8_t* row, const std::uint8_t* above,
                 std::size_t rowBytes, std::size_t bytesPerPixel) {
  switch (filter) {
    case 0:  // None
      return true;
    case 1:  // Sub
      for (std::size_t i = bytesPerPixel; i < rowBytes; ++i)
        row[i] = std::uint8_t(row[i] + row[i - bytesPerPixel]);
      return true;
    case 2:  // Up
      if (above) {
        for (std::size_t i = 0; i < rowBytes; ++i)
          row[i] = std::uint8_t(row[i] + above[i]);
      }
      return true;
    case 3:  // Average
      for (std::size_t i = 0; i < rowBytes; ++i) {
        const int left = i >= bytesPerPixel ? row[i - bytesPerPixel] : 0;
        const int up = above ? above[i] : 0;
        row[i] = std::uint8_t(row[i] + ((left + up) >> 1));
      }
      return true;
    case 4:  // Paeth
      for (std::size_t i = 0; i < rowBytes; ++i) {
        const bool hasLeft = i >= bytesPerPixel;
        const int a = hasLeft ? row[i - bytesPerPixel] : 0;
        const int b = above ? above[i] : 0;
        const int c = (hasLeft && above) ? above[i - bytesPerPixel] : 0;
        const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
        const int predictor = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
        row[i] = std::uint8_t(row[i] + predictor);
      }
      return true;
    default:
      return false;
  }
}

Error damaged(const std::string& path, const std::string& what) {
  return makeError(path + ": the pixel data is damaged or truncated (" + what + ")");
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

  // Walk the chunks; the IDAT payloads are moved together to the front of `bytes` (the file's
  // own buffer, so no second copy of the compressed stream).
  Header header;
  bool sawHeader = false, sawEnd = false;
  std::size_t compressed = 0;
  std::size_t at = sizeof kSignature;
  while (at + 12 <= bytes.size() && !sawEnd) {
    const std::uint32_t length = bigEndian32(&bytes[at]);
    if (length > 0x7fffffffu || std::size_t(length) + 12 > bytes.size() - at)
      return damaged(path, "a chunk runs past the end of the file");
    const std::uint8_t* type = &bytes[at + 4];
    const std::uint8_t* data = type + 4;
    const std::uint32_t storedCrc = bigEndian32(data + length);
    const bool critical = (type[0] & 0x20) == 0;  // upper-case first letter
    if (critical && libdeflate_crc32(0, type, length + 4) != storedCrc) {
      return damaged(path, "the CRC of chunk \"" + std::string(type, type + 4) + "\" at byte " +
                               std::to_string(at) + " does not match");
    }
    if (std::memcmp(type, "IHDR", 4) == 0) {
      if (length != 13)
        return damaged(path, "the IHDR chunk is not 13 bytes");
      header.width = bigEndian32(data);
      header.height = bigEndian32(data + 4);
      header.bitDepth = data[8];
      header.colourType = data[9];
      header.interlace = data[12];
      sawHeader = true;
    } else if (std::memcmp(type, "IDAT", 4) == 0) {
      std::memmove(&bytes[compressed], data, length);  // never overlaps forward: compressed < at
      compressed += length;
    } else if (std::memcmp(type, "PLTE", 4) == 0 || std::memcmp(type, "tRNS", 4) == 0) {
      return PngFastDecode::NotHandled;  // palettes and colour-key transparency: OpenImageIO's
    } else if (std::memcmp(type, "IEND", 4) == 0) {
      sawEnd = true;
    }
    at += std::size_t(length) + 12;
  }
  const int channels = channelsOf(header.colourType);
  if (!sawHeader || channels == 0 || header.interlace != 0 ||
      (header.bitDepth != 8 && header.bitDepth != 16))
    return PngFastDecode::NotHandled;
  if (header.width != std::uint32_t(image.width()) ||
      header.height != std::uint32_t(image.height()) || channels != image.channels())
    return PngFastDecode::NotHandled;  // OpenImageIO saw something else; trust its reading

  const std::size_t bytesPerSample = std::size_t(header.bitDepth / 8);
  const std::size_t bytesPerPixel = bytesPerSample * std::size_t(channels);
  const std::size_t rowBytes = bytesPerPixel * header.width;
  const std::size_t inflatedBytes = (rowBytes + 1) * header.height;
  if (inflatedBytes > kMaxInflatedBytes)
    return PngFastDecode::NotHandled;
  if (compressed == 0)
    return damaged(path, "no IDAT chunk");

  std::unique_ptr<std::uint8_t[]> raw(new (std::nothrow) std::uint8_t[inflatedBytes]);
  if (!raw)
    return makeError(path + ": not enough memory to decode " + std::to_string(header.width) + "x" +
                     std::to_string(header.height) + " pixels");
  {
    const std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> inflater(
        libdeflate_alloc_decompressor(), libdeflate_free_decompressor);
    if (!inflater)
      return makeError(path + ": not enough memory to decode");
    // With no "actual size" out-parameter libdeflate demands exactly `inflatedBytes`: a short or
    // long stream fails like a corrupt one. It checks the Adler-32 too.
    const libdeflate_result result = libdeflate_zlib_decompress(
        inflater.get(), bytes.data(), compressed, raw.get(), inflatedBytes, nullptr);
    if (result != LIBDEFLATE_SUCCESS) {
      return damaged(path, result == LIBDEFLATE_SHORT_OUTPUT ? "the zlib stream ends early"
                           : result == LIBDEFLATE_INSUFFICIENT_SPACE
                               ? "the zlib stream holds more than the image"
                               : "the zlib stream is corrupt");
    }
  }
  bytes = {};

  // Unfiltering is sequential (each row predicts from the one above); the conversion to floats
  // is not, and runs in parallel afterwards.
  for (std::uint32_t y = 0; y < header.height; ++y) {
    std::uint8_t* line = raw.get() + std::size_t(y) * (rowBytes + 1);
    const std::uint8_t* above = y > 0 ? line - rowBytes : nullptr;
    if (!unfilterRow(line[0], line + 1, above, rowBytes, bytesPerPixel)) {
      return damaged(path, "row " + std::to_string(y) + " has the unknown filter type " +
                               std::to_string(int(line[0])));
    }
  }
  const std::size_t values = std::size_t(header.width) * std::size_t(channels);
  const int blocks = int((header.height + kRowsPerBlock - 1) / kRowsPerBlock);
  parallelFor(blocks, [&](int block) {
    const int first = block * kRowsPerBlock;
    const int last = std::min(first + kRowsPerBlock, int(header.height));
    for (int y = first; y < last; ++y) {
      const std::uint8_t* source = raw.get() + std::size_t(y) * (rowBytes + 1) + 1;
      float* target = image.pixel(0, y);
      if (bytesPerSample == 2) {
        for (std::size_t i = 0; i < values; ++i)
          target[i] = float(source[2 * i] << 8 | source[2 * i + 1]) * (1.0f / 65535.0f);
      } else {
        for (std::size_t i = 0; i < values; ++i)
          target[i] = float(source[i]) * (1.0f / 255.0f);
      }
    }
  });
  return PngFastDecode::Decoded;
}

}  // namespace relief::core::inline image
