#include "core/image/PngPreflight.h"

#include <algorithm>
#include <fstream>

namespace relief::core::inline image {

Status preflightPng(const std::string& path, std::uintmax_t fileBytes) {
  std::ifstream file(path, std::ios::binary);
  // Only files with PNG's signature have chunks; for others the PNG reader says what they are.
  static const char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  char signature[8] = {};
  if (!file.read(signature, 8) || !std::equal(signature, signature + 8, kSignature))
    return {};
  // Chunk headers only: eight bytes each, then a seek past the data and its CRC.
  std::uintmax_t at = 8;  // after the signature
  while (at + 8 <= fileBytes) {
    unsigned char header[8] = {};
    file.seekg(std::streamoff(at));
    if (!file.read(reinterpret_cast<char*>(header), 8))
      return makeError(path + ": cannot be read (the chunk at byte " + std::to_string(at) + ")");
    const std::uint32_t length = std::uint32_t(header[0]) << 24 | std::uint32_t(header[1]) << 16 |
                                 std::uint32_t(header[2]) << 8 | std::uint32_t(header[3]);
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
    at += 12 + std::uintmax_t(length);
    if (type == "IEND")
      break;
  }
  return {};
}

}  // namespace relief::core::inline image
