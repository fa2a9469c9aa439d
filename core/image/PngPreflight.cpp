#include "core/image/PngPreflight.h"

#include <algorithm>
#include <fstream>

namespace relief::core::inline image {
namespace {

// Deflate never compresses better than 1032:1 (a run of 258 bytes costs at least two bits).
constexpr std::uint64_t kDeflateBestRatio = 1032;

std::uint32_t bigEndian32(const unsigned char* bytes) {
  return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 |
         std::uint32_t(bytes[2]) << 8 | std::uint32_t(bytes[3]);
}

// Samples per pixel as stored (PNG section 6.1); an unknown type counts one, so the bound stays a
// lower one and libpng names the real problem.
int storedSamples(int colourType) {
  switch (colourType) {
    case 2:
      return 3;  // RGB
    case 4:
      return 2;  // grey and alpha
    case 6:
      return 4;  // RGBA
    default:
      return 1;  // grey (0), palette index (3)
  }
}

}  // namespace

std::uint64_t pngMinimumInflatedBytes(std::uint32_t width, std::uint32_t height, int bitDepth,
                                      int colourType) {
  const std::uint64_t rowBits =
      std::uint64_t(width) * std::uint64_t(storedSamples(colourType)) * std::uint64_t(bitDepth);
  return (1 + (rowBits + 7) / 8) * std::uint64_t(height);
}

Status preflightPng(const std::string& path, std::uintmax_t fileBytes) {
  std::ifstream file(path, std::ios::binary);
  // Only files with PNG's signature have chunks; for others the PNG reader says what they are.
  static const char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  char signature[8] = {};
  if (!file.read(signature, 8) || !std::equal(signature, signature + 8, kSignature))
    return {};
  std::uint64_t inflatedAtLeast = 0;  // from IHDR, which the specification puts first
  std::uint64_t idatBytes = 0;
  std::string size;  // "WxH", for the message
  // Chunk headers (and IHDR's data) only: a seek past the rest of each chunk and its CRC.
  std::uintmax_t at = 8;  // after the signature
  while (at + 8 <= fileBytes) {
    unsigned char header[8] = {};
    file.seekg(std::streamoff(at));
    if (!file.read(reinterpret_cast<char*>(header), 8))
      return makeError(path + ": cannot be read (the chunk at byte " + std::to_string(at) + ")");
    const std::uint32_t length = bigEndian32(header);
    std::string type(reinterpret_cast<const char*>(header + 4), 4);
    for (char& c : type) {
      if (c < 0x20 || c > 0x7e)
        c = '?';
    }
    const std::uintmax_t after = fileBytes - (at + 8);
    if (length > 0x7fffffffu || std::uintmax_t(length) + 4 > after) {
      return makeError(path + ": the PNG is truncated or damaged: chunk \"" + type + "\" at byte " +
                       std::to_string(at) + " claims " + std::to_string(length) +
                       " bytes; the file has " + std::to_string(after) + " after its header");
    }
    unsigned char ihdr[13] = {};
    if (type == "IHDR" && length == 13 && file.read(reinterpret_cast<char*>(ihdr), 13)) {
      const std::uint32_t width = bigEndian32(ihdr), height = bigEndian32(ihdr + 4);
      inflatedAtLeast = pngMinimumInflatedBytes(width, height, ihdr[8], ihdr[9]);
      size = std::to_string(width) + "x" + std::to_string(height);
    } else if (type == "IDAT") {
      idatBytes += length;
    }
    at += 12 + std::uintmax_t(length);
    if (type == "IEND")
      break;
  }
  // Checked before the pixels' memory is allocated: a 300-byte file claiming 16384x16384 RGBA
  // would take 4 GiB. The bound counts the samples as stored, so a 409-byte palette file of
  // 512x512 (one index byte a pixel) passes where counting the RGB it expands to refused it.
  if (idatBytes * kDeflateBestRatio < inflatedAtLeast) {
    return makeError(path + ": its " + std::to_string(idatBytes) +
                     " bytes of compressed pixel data (IDAT) cannot hold " + size +
                     " pixels even at deflate's best ratio (1:1032); the file is cut short or "
                     "its header is damaged");
  }
  return {};
}

}  // namespace relief::core::inline image
