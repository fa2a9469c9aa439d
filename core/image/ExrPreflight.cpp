#include "core/image/ExrPreflight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <vector>

namespace relief::core::inline image {
namespace {

constexpr std::uint32_t kTiledFlag = 0x200;
constexpr std::uint32_t kMultipartFlag = 0x1000;
// Headers are a few KiB; more than this is not a header worth reading.
constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 20;

std::uint32_t le32(const std::vector<char>& b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// Scanlines per chunk for each compression (OpenEXR's Compression enum, in order).
int linesPerChunk(int compression) {
  static constexpr int kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression >= 0 && compression < int(std::size(kLines)) ? kLines[compression] : 1;
}

std::uint64_t tilesIn(std::uint64_t width, std::uint64_t height, std::uint64_t tileW,
                      std::uint64_t tileH) {
  return ((width + tileW - 1) / tileW) * ((height + tileH - 1) / tileH);
}

// Chunks in a tiled part: every tile of every level (tiledesc: x size, y size, mode with the
// level mode in the low nibble and the rounding mode in the next).
std::uint64_t tiledChunks(std::uint64_t width, std::uint64_t height, std::uint32_t tileW,
                          std::uint32_t tileH, unsigned mode) {
  const unsigned levelMode = mode & 0xf;
  const bool roundUp = ((mode >> 4) & 0xf) == 1;
  const auto levelsFor = [roundUp](std::uint64_t size) {
    const double l = std::log2(double(size));
    return std::uint64_t(roundUp ? std::ceil(l) : std::floor(l)) + 1;
  };
  const auto levelSize = [roundUp](std::uint64_t size, std::uint64_t level) {
    const std::uint64_t divisor = std::uint64_t(1) << level;
    return std::max<std::uint64_t>(1, roundUp ? (size + divisor - 1) / divisor : size / divisor);
  };
  if (levelMode == 0)
    return tilesIn(width, height, tileW, tileH);
  std::uint64_t total = 0;
  if (levelMode == 1) {  // mip map: square levels
    for (std::uint64_t l = 0; l < levelsFor(std::max(width, height)); ++l)
      total += tilesIn(levelSize(width, l), levelSize(height, l), tileW, tileH);
  } else {  // rip map: every pair of x and y levels
    for (std::uint64_t lx = 0; lx < levelsFor(width); ++lx)
      for (std::uint64_t ly = 0; ly < levelsFor(height); ++ly)
        total += tilesIn(levelSize(width, lx), levelSize(height, ly), tileW, tileH);
  }
  return total;
}

}  // namespace

Status preflightExr(const std::string& path, std::uintmax_t fileBytes) {
  std::ifstream file(path, std::ios::binary);
  std::vector<char> b(std::min<std::uintmax_t>(fileBytes, kMaxHeaderBytes));
  file.read(b.data(), std::streamsize(b.size()));
  const auto fail = [&path](const std::string& problem) {
    return makeError(path + ": a damaged OpenEXR header: " + problem);
  };
  if (b.size() < 8)
    return fail("the file ends inside it");
  const std::uint32_t version = le32(b, 4);
  if (version & kMultipartFlag)
    return {};  // several headers; OpenEXR checks those (Relief reads the first part)
  std::size_t at = 8;
  std::optional<std::array<std::int32_t, 4>> window;
  int compression = 0;
  std::optional<std::array<std::uint32_t, 2>> tile;
  unsigned tileMode = 0;
  while (true) {
    if (at >= b.size())
      return fail("the attribute list has no end within " + std::to_string(b.size()) + " bytes");
    if (b[at] == '\0')
      break;
    const auto nameEnd = std::find(b.begin() + std::ptrdiff_t(at), b.end(), '\0');
    const auto typeEnd = nameEnd == b.end() ? b.end() : std::find(nameEnd + 1, b.end(), '\0');
    if (typeEnd == b.end() || b.end() - typeEnd < 5)
      return fail("an attribute is cut short");
    const std::string name(b.begin() + std::ptrdiff_t(at), nameEnd);
    const std::size_t valueAt = std::size_t(typeEnd - b.begin()) + 5;
    const std::uint32_t size = le32(b, valueAt - 4);
    if (size > b.size() - valueAt) {
      return fail("attribute \"" + name + "\" claims " + std::to_string(size) +
                  " bytes; the file has " + std::to_string(b.size() - valueAt) + " after it");
    }
    if (name == "dataWindow" && size == 16) {
      std::array<std::int32_t, 4> box{};
      std::memcpy(box.data(), b.data() + valueAt, 16);
      window = box;
    } else if (name == "compression" && size == 1) {
      compression = static_cast<unsigned char>(b[valueAt]);
    } else if (name == "tiles" && size == 9) {
      tile = {le32(b, valueAt), le32(b, valueAt + 4)};
      tileMode = static_cast<unsigned char>(b[valueAt + 8]);
    }
    at = valueAt + size;
  }
  if (!window)
    return {};  // OpenEXR refuses a header without a data window itself
  const std::int64_t width = std::int64_t((*window)[2]) - (*window)[0] + 1;
  const std::int64_t height = std::int64_t((*window)[3]) - (*window)[1] + 1;
  if (width < 1 || height < 1)
    return {};  // an empty or inverted window: OpenEXR says so
  std::uint64_t chunks = 0;
  if ((version & kTiledFlag) && tile) {
    if ((*tile)[0] == 0 || (*tile)[1] == 0)
      return {};  // OpenEXR refuses zero-sized tiles
    chunks =
        tiledChunks(std::uint64_t(width), std::uint64_t(height), (*tile)[0], (*tile)[1], tileMode);
  } else {
    chunks = (std::uint64_t(height) + linesPerChunk(compression) - 1) / linesPerChunk(compression);
  }
  // The offset table alone takes 8 bytes per chunk, before any pixel.
  const std::uint64_t tableBytes = chunks * 8;
  if (tableBytes > fileBytes - (at + 1)) {
    return fail(std::to_string(width) + "x" + std::to_string(height) + " in " +
                std::to_string(chunks) + " chunks needs a " + std::to_string(tableBytes) +
                "-byte offset table; the file has " + std::to_string(fileBytes - (at + 1)) +
                " bytes after the header");
  }
  return {};
}

}  // namespace relief::core::inline image
