// PngPreflight; see PngPreflight.h. Chunk rules from the PNG specification (ISO/IEC 15948, third
// edition); which chunks decide the colour space, from OpenImageIO 2.4's PNG reader
// (src/png.imageio/png_pvt.h, read_info) and libpng 1.6's chunk handlers.
#include "core/image/PngPreflight.h"

#include "core/image/PngFormat.h"

#include <libdeflate.h>

#include <strings.h>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <vector>

namespace relief::core::inline image {
namespace {

using png::bigEndian32;

// Deflate never compresses better than 1032:1 (a run of 258 bytes costs at least two bits).
constexpr std::uint64_t kDeflateBestRatio = 1032;
// Text chunks longer than this cannot hold a colour-space name worth reading.
constexpr std::uint32_t kLongestTextRead = 4096;

// The value of a text chunk (tEXt, zTXt or iTXt; sections 11.3.4.3-5) whose keyword is
// "oiio:ColorSpace" (in any case, as OpenImageIO finds attributes), or nothing.
std::optional<std::string> colorSpaceText(const std::string& type,
                                          const std::vector<std::uint8_t>& data) {
  const auto* begin = reinterpret_cast<const char*>(data.data());
  const auto* end = begin + data.size();
  const char* keyEnd = std::find(begin, end, '\0');
  static constexpr char kKey[] = "oiio:ColorSpace";
  if (keyEnd == end || std::size_t(keyEnd - begin) != sizeof kKey - 1 ||
      strncasecmp(begin, kKey, sizeof kKey - 1) != 0)
    return std::nullopt;
  const char* rest = keyEnd + 1;
  bool compressed = false;
  if (type == "zTXt") {
    if (rest == end || *rest != 0)
      return std::nullopt;  // compression method 0 (zlib) is the only one defined
    compressed = true;
    ++rest;
  } else if (type == "iTXt") {
    if (end - rest < 2 || rest[1] != 0)
      return std::nullopt;
    compressed = rest[0] != 0;
    rest += 2;
    for (int skip = 0; skip < 2; ++skip) {  // language tag, translated keyword
      rest = std::find(rest, end, '\0');
      if (rest == end)
        return std::nullopt;
      ++rest;
    }
  }
  if (!compressed)
    return std::string(rest, end);
  char inflated[256];
  std::size_t inflatedBytes = 0;
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  if (!inflater)
    return std::nullopt;
  const libdeflate_result result = libdeflate_zlib_decompress(
      inflater, rest, std::size_t(end - rest), inflated, sizeof inflated, &inflatedBytes);
  libdeflate_free_decompressor(inflater);
  if (result != LIBDEFLATE_SUCCESS)
    return std::nullopt;
  return std::string(inflated, inflatedBytes);
}

Error invalid(const std::string& path, const std::string& what) {
  return makeError(path + ": not a valid PNG (" + what + ")");
}

}  // namespace

int PngHeader::channels() const {
  const int stored = colourType == 3 ? 3 : png::storedSamplesOf(colourType);
  const bool keyAddsAlpha =
      transparencyChunk && (colourType == 0 || colourType == 2 || colourType == 3);
  return stored + (keyAddsAlpha ? 1 : 0);
}

std::uint64_t pngMinimumInflatedBytes(std::uint32_t width, std::uint32_t height, int bitDepth,
                                      int colourType) {
  // Reserved colour types count one sample, so the bound stays a lower one.
  const int samples = std::max(1, png::storedSamplesOf(colourType));
  const std::uint64_t rowBits =
      std::uint64_t(width) * std::uint64_t(samples) * std::uint64_t(bitDepth);
  return (1 + (rowBits + 7) / 8) * std::uint64_t(height);
}

namespace {

// What the chunks read so far say.
struct PngChunkState {
  PngHeader header;
  bool sawHeader = false, sawPalette = false, sawData = false, sawIcc = false;
  std::optional<ColorSpace> fromSrgbOrGamma;
  std::optional<std::string> colorSpaceName;
  std::uint64_t idatBytes = 0;
};

// The header chunk IHDR: 13 bytes with a matching CRC, a size, a colour type and bit depth PNG
// allows, and methods it knows.
Status readHeaderChunk(const std::string& path, const std::vector<std::uint8_t>& data,
                       std::uint32_t length, bool crcMatches, PngHeader& header) {
  if (length != 13)
    return invalid(path, "the header chunk IHDR is not 13 bytes");
  if (!crcMatches)
    return invalid(path, "the CRC of the header chunk IHDR does not match");
  header.width = bigEndian32(data.data());
  header.height = bigEndian32(data.data() + 4);
  header.bitDepth = data[8];
  header.colourType = data[9];
  header.interlace = data[12];
  if (header.width == 0 || header.height == 0 || header.width > 0x7fffffffu ||
      header.height > 0x7fffffffu)
    return invalid(path, "the header gives the size " + std::to_string(header.width) + "x" +
                             std::to_string(header.height));
  if (!png::allowedDepth(header.colourType, header.bitDepth))
    return invalid(path, "colour type " + std::to_string(header.colourType) + " with bit depth " +
                             std::to_string(header.bitDepth));
  if (data[10] != 0 || data[11] != 0 || header.interlace > 1)
    return invalid(path, "unknown compression, filter or interlace method in IHDR");
  return {};
}

// An ancillary chunk before the image data whose CRC matches: sRGB, gAMA and iCCP as libpng
// weighs them, tRNS, and a text chunk naming a colour space. libpng ignores an ancillary chunk
// that fails its CRC or comes out of place.
void readAncillaryChunk(const std::string& type, const std::vector<std::uint8_t>& data,
                        std::uint32_t length, bool textChunk, PngChunkState& state) {
  const bool beforePalette = !state.sawPalette;
  if (type == "sRGB" && beforePalette && length == 1 && data[0] <= 3 && !state.sawIcc) {
    state.fromSrgbOrGamma = ColorSpace::Srgb;
  } else if (type == "gAMA" && beforePalette && length == 4 && !state.fromSrgbOrGamma) {
    // The file stores the encoding gamma times 100000; libpng accepts 16 to 625000000.
    const std::uint32_t stored = bigEndian32(data.data());
    if (stored >= 16 && stored <= 625000000u) {
      // OpenImageIO rounds the decoding gamma (1/stored) to hundredths: 1.00 is linear.
      const float decoding = std::round(100.0f * float(100000.0 / double(stored))) / 100.0f;
      state.fromSrgbOrGamma = decoding == 1.0f ? ColorSpace::Linear : ColorSpace::Srgb;
    }
  } else if (type == "iCCP" && beforePalette) {
    state.sawIcc = true;  // libpng then ignores a later sRGB chunk ("too many profiles")
  } else if (type == "tRNS") {
    const bool fits = state.header.colourType == 0   ? length == 2
                      : state.header.colourType == 2 ? length == 6
                      : state.header.colourType == 3 ? state.sawPalette && length > 0
                                                     : false;
    state.header.transparencyChunk = fits;
  } else if (textChunk) {
    if (std::optional<std::string> name = colorSpaceText(type, data))
      state.colorSpaceName = std::move(name);
  }
}

// The checks once every chunk is read, and the colour space the chunks give.
Result<PngHeader> checkedHeader(const std::string& path, const PngChunkState& state) {
  if (!state.sawHeader)
    return invalid(path, "no header chunk IHDR");
  if (state.header.colourType == 3 && !state.sawPalette)
    return invalid(path, "a palette image without a palette (PLTE)");
  if (!state.sawData)
    return invalid(path, "no image data (IDAT)");
  // Checked before the pixels' memory is allocated: a 300-byte file claiming 16384x16384 RGBA
  // would take 4 GiB. The bound counts the samples as stored, so a 409-byte palette file of
  // 512x512 (one index byte a pixel) passes where counting the RGB it expands to refused it.
  const std::uint64_t inflatedAtLeast = pngMinimumInflatedBytes(
      state.header.width, state.header.height, state.header.bitDepth, state.header.colourType);
  if (state.idatBytes * kDeflateBestRatio < inflatedAtLeast) {
    return makeError(path + ": its " + std::to_string(state.idatBytes) +
                     " bytes of compressed pixel data (IDAT) cannot hold " +
                     std::to_string(state.header.width) + "x" +
                     std::to_string(state.header.height) +
                     " pixels even at deflate's best ratio (1:1032); the file is cut short or "
                     "its header is damaged");
  }
  PngHeader header = state.header;
  header.colorSpace = state.colorSpaceName ? colorSpaceFromOiioName(*state.colorSpaceName)
                                           : state.fromSrgbOrGamma.value_or(ColorSpace::Srgb);
  return header;
}

}  // namespace

Result<PngHeader> preflightPng(const std::string& path, std::uintmax_t fileBytes) {
  // Unbuffered: the walk reads 8 bytes a chunk and seeks past the data, and a buffered stream
  // refills its whole buffer after every seek, reading the file's image data (a 2048^2 map's
  // 8 KiB IDAT chunks: 6 MB in 700 reads) only to throw it away.
  std::ifstream file;
  file.rdbuf()->pubsetbuf(nullptr, 0);
  file.open(path, std::ios::binary);
  std::uint8_t signature[8] = {};
  if (!file.read(reinterpret_cast<char*>(signature), 8) ||
      !std::equal(signature, signature + 8, png::kSignature))
    return makeError(path +
                     ": cannot read as an image (named .png, but the file does not start "
                     "with PNG's signature)");
  PngChunkState state;
  std::vector<std::uint8_t> data;
  // Chunk headers, and the data of the few chunks before the image data that say something
  // about the decoded image; a seek past the rest.
  std::uintmax_t at = 8;  // after the signature
  while (at + 8 <= fileBytes) {
    std::uint8_t head[8] = {};
    file.seekg(std::streamoff(at));
    if (!file.read(reinterpret_cast<char*>(head), 8))
      return makeError(path + ": cannot be read (the chunk at byte " + std::to_string(at) + ")");
    const std::uint32_t length = bigEndian32(head);
    std::string type(reinterpret_cast<const char*>(head + 4), 4);
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
    if (!state.sawHeader && type != "IHDR")
      return invalid(path, "the first chunk is \"" + type + "\", not the header IHDR");
    const bool beforeData = !state.sawData && type != "IDAT";
    const bool textChunk = type == "tEXt" || type == "zTXt" || type == "iTXt";
    const bool wanted =
        type == "IHDR" ||
        (beforeData && (type == "gAMA" || type == "sRGB" || type == "tRNS" || type == "iCCP" ||
                        (textChunk && length <= kLongestTextRead)));
    bool crcMatches = false;
    if (wanted) {
      data.resize(std::size_t(length) + 4);
      if (!file.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size())))
        return makeError(path + ": cannot be read (chunk \"" + type + "\")");
      const std::uint32_t stored = bigEndian32(&data[length]);
      data.resize(length);
      crcMatches =
          libdeflate_crc32(libdeflate_crc32(0, head + 4, 4), data.data(), length) == stored;
    }
    if (type == "IHDR") {
      if (state.sawHeader)
        return invalid(path, "a second header chunk IHDR");
      if (Status read = readHeaderChunk(path, data, length, crcMatches, state.header); !read)
        return makeError(read.error());
      state.sawHeader = true;
    } else if (type == "PLTE") {
      state.sawPalette = true;
    } else if (type == "IDAT") {
      state.sawData = true;
      state.idatBytes += length;
    } else if (wanted && crcMatches) {
      readAncillaryChunk(type, data, length, textChunk, state);
    }
    at += 12 + std::uintmax_t(length);
    if (type == "IEND")
      break;
  }
  return checkedHeader(path, state);
}

}  // namespace relief::core::inline image
