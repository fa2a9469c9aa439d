#include "core/image/TiffPreflight.h"

#include <cstdint>
#include <fstream>
#include <vector>

namespace relief::core::inline image {
namespace {

constexpr int kBitsPerSampleTag = 258;
constexpr std::size_t kDirectoryEntryBytes = 12;  // tag, type, count, value or offset

}  // namespace

Status preflightTiff(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  unsigned char header[8] = {};
  if (!file.read(reinterpret_cast<char*>(header), sizeof header))
    return {};
  const bool little = header[0] == 'I';
  const auto read16 = [little](const unsigned char* p) {
    return little ? std::uint32_t(p[0] | p[1] << 8) : std::uint32_t(p[0] << 8 | p[1]);
  };
  const auto read32 = [little](const unsigned char* p) {
    return little ? std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                        std::uint32_t(p[3]) << 24
                  : std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 |
                        std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
  };
  if (read16(header + 2) != 42)
    return {};  // BigTIFF (43) or not a TIFF: left to the reader
  unsigned char countBytes[2] = {};
  file.seekg(std::streamoff(read32(header + 4)));
  if (!file.read(reinterpret_cast<char*>(countBytes), sizeof countBytes))
    return {};
  const std::uint32_t entries = read16(countBytes);
  std::vector<unsigned char> directory(entries * kDirectoryEntryBytes);
  if (!file.read(reinterpret_cast<char*>(directory.data()), std::streamsize(directory.size())))
    return {};
  for (std::uint32_t e = 0; e < entries; ++e) {
    if (read16(directory.data() + e * kDirectoryEntryBytes) == kBitsPerSampleTag)
      return {};
  }
  return makeError(path +
                   ": a TIFF without a BitsPerSample tag (1 bit a sample, as the TIFF "
                   "specification defaults it), which OpenImageIO 2.4 misreads as 8 bits; "
                   "re-save it with the tag, e.g. `convert IN.tif -depth 1 OUT.tif` or as PNG");
}

}  // namespace relief::core::inline image
