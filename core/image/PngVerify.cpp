// PngVerify; see PngVerify.h. Layout from the PNG specification (ISO/IEC 15948, third edition):
// chunks (section 5.3), the zlib stream split across IDAT chunks (10.1), filters (9.2) and the
// Adam7 passes (8.2). zlib's streaming inflate here, where PngReader inflates all at once with
// libdeflate: streaming is what keeps the memory to a few rows.
#include "core/image/PngVerify.h"

#include "core/image/PngFormat.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <optional>
#include <vector>

namespace relief::core::inline image {
namespace {

// Takes the inflated stream in pieces and checks it row by row: filter types, and for palette
// images each index (which needs the rows unfiltered).
class RowChecker {
 public:
  RowChecker(const PngHeader& header, int paletteEntries)
      : m_header(header),
        m_paletteEntries(paletteEntries),
        m_stride(png::filterStride(header.bitDepth, header.colourType)) {
    startPass(0);
  }

  // Consumes `size` inflated bytes; an error names the problem. Bytes past the last row are an
  // error too: the stream holds more than the image.
  std::string take(const std::uint8_t* bytes, std::size_t size) {
    while (size > 0) {
      if (m_pass >= png::passCount(m_header.interlace))
        return "the zlib stream holds more than the image";
      const std::size_t n = std::min(size, m_line.size() - m_filled);
      std::copy(bytes, bytes + n, m_line.begin() + std::ptrdiff_t(m_filled));
      m_filled += n;
      bytes += n;
      size -= n;
      if (m_filled == m_line.size()) {
        if (std::string problem = finishRow(); !problem.empty())
          return problem;
      }
    }
    return {};
  }

  bool complete() const { return m_pass >= png::passCount(m_header.interlace); }

 private:
  void startPass(int pass) {
    // Empty passes (images narrower or shorter than Adam7's grid) store nothing.
    for (m_pass = pass; m_pass < png::passCount(m_header.interlace); ++m_pass) {
      m_geometry = png::passOf(m_header.interlace, m_pass, m_header.width, m_header.height);
      if (m_geometry.width > 0 && m_geometry.height > 0)
        break;
    }
    if (complete())
      return;
    const std::size_t rowBytes =
        png::rowBytesOf(m_geometry.width, m_header.bitDepth, m_header.colourType);
    m_line.assign(rowBytes + 1, 0);
    m_above.assign(rowBytes, 0);
    m_filled = 0;
    m_row = 0;
  }

  std::string finishRow() {
    const std::uint8_t filter = m_line[0];
    const std::size_t rowBytes = m_line.size() - 1;
    const bool first = m_row == 0;
    if (!png::unfilterRow(filter, m_line.data() + 1, first ? nullptr : m_above.data(), rowBytes,
                          m_stride))
      return "a row has the unknown filter type " + std::to_string(int(filter));
    if (m_header.colourType == 3) {
      const int depth = m_header.bitDepth;
      const std::uint8_t* row = m_line.data() + 1;
      for (std::uint32_t x = 0; x < m_geometry.width; ++x) {
        const std::size_t bit = std::size_t(x) * std::size_t(depth);
        const int index = (row[bit / 8] >> (8 - depth - int(bit % 8))) & ((1 << depth) - 1);
        if (index >= m_paletteEntries) {
          const std::uint32_t px = m_geometry.xStart + x * m_geometry.xStep;
          const std::uint32_t py = m_geometry.yStart + m_row * m_geometry.yStep;
          return "pixel (" + std::to_string(px) + ", " + std::to_string(py) +
                 ") uses palette index " + std::to_string(index) + "; the palette has " +
                 std::to_string(m_paletteEntries) + " entries";
        }
      }
    }
    std::copy(m_line.begin() + 1, m_line.end(), m_above.begin());
    m_filled = 0;
    if (++m_row == m_geometry.height)
      startPass(m_pass + 1);
    return {};
  }

  const PngHeader& m_header;
  const int m_paletteEntries;
  const std::size_t m_stride;
  int m_pass = 0;
  png::PngPass m_geometry{};
  std::uint32_t m_row = 0;
  std::vector<std::uint8_t> m_line;   // the row being filled: filter byte, then the row
  std::vector<std::uint8_t> m_above;  // the previous row of the pass, unfiltered
  std::size_t m_filled = 0;
};

}  // namespace

Status verifyPngData(const std::string& path, const PngHeader& header) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    return makeError(path + ": cannot be opened for reading");
  file.seekg(8);  // preflightPng has checked the signature
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK)
    return makeError(path + ": not enough memory to check the pixel data");
  struct End {
    z_stream& stream;
    ~End() { inflateEnd(&stream); }
  } end{stream};

  int paletteEntries = 0;
  bool streamEnded = false, sawEnd = false;
  std::optional<RowChecker> rows;
  std::vector<std::uint8_t> piece(64 * 1024);
  std::array<std::uint8_t, 64 * 1024> inflated{};
  std::uintmax_t at = 8;
  while (!sawEnd) {
    std::uint8_t head[8];
    if (!file.read(reinterpret_cast<char*>(head), 8))
      break;  // no IEND: the data's completeness below decides
    const std::uint32_t length = png::bigEndian32(head);
    const std::string type(reinterpret_cast<const char*>(head + 4), 4);
    const bool critical = (head[4] & 0x20) == 0;
    uLong crc = crc32(crc32(0, nullptr, 0), head + 4, 4);
    const bool idat = type == "IDAT";
    if (idat && !rows)
      rows.emplace(header, paletteEntries);
    std::vector<std::uint8_t> palette;
    for (std::uint32_t left = length; left > 0;) {
      const std::uint32_t n = std::min<std::uint32_t>(left, std::uint32_t(piece.size()));
      if (!file.read(reinterpret_cast<char*>(piece.data()), n))
        return png::damagedPixelData(path, "the file ends inside chunk \"" + type + "\"");
      crc = crc32(crc, piece.data(), n);
      left -= n;
      if (type == "PLTE")
        palette.insert(palette.end(), piece.begin(), piece.begin() + n);
      if (!idat || streamEnded)
        continue;
      stream.next_in = piece.data();
      stream.avail_in = n;
      // Until this piece is used up and zlib has no output pending (a full output buffer may
      // leave some).
      do {
        stream.next_out = inflated.data();
        stream.avail_out = uInt(inflated.size());
        const int status = inflate(&stream, Z_NO_FLUSH);
        if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR)
          return png::damagedPixelData(path, "the zlib stream is corrupt");
        if (std::string problem = rows->take(inflated.data(), inflated.size() - stream.avail_out);
            !problem.empty())
          return png::damagedPixelData(path, problem);
        streamEnded = status == Z_STREAM_END;
      } while (!streamEnded && (stream.avail_in > 0 || stream.avail_out == 0));
    }
    std::uint8_t stored[4];
    if (!file.read(reinterpret_cast<char*>(stored), 4))
      return png::damagedPixelData(path, "the file ends inside chunk \"" + type + "\"");
    if (critical && crc != png::bigEndian32(stored)) {
      return png::damagedPixelData(path, "the CRC of chunk \"" + type + "\" at byte " +
                                             std::to_string(at) + " does not match");
    }
    if (type == "PLTE")
      paletteEntries = int(std::min<std::size_t>(256, palette.size() / 3));
    sawEnd = type == "IEND";
    at += 12 + std::uintmax_t(length);
  }
  if (!rows)
    return png::damagedPixelData(path, "no IDAT chunk");
  if (!streamEnded)
    return png::damagedPixelData(path, "the zlib stream ends early");
  if (!rows->complete())
    return png::damagedPixelData(path, "the zlib stream ends before the last row");
  return {};
}

}  // namespace relief::core::inline image
