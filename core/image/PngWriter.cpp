// PngWriter; see PngWriter.h. Chunk layout, filters and the zlib stream as the PNG
// specification (ISO/IEC 15948, third edition) defines them.
#include "core/image/PngWriter.h"

#include "core/base/ParallelFor.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace relief::core::inline image {
namespace {

// Rows are compressed in strips of about this many bytes: enough strips to keep every core
// busy and small buffers, large enough that each strip's own deflate stream costs nothing
// measurable (the run-length strategy keeps no dictionary across strips anyway).
constexpr std::size_t kStripBytes = std::size_t(1) << 20;

constexpr std::uint8_t kPaethFilter = 4;

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(std::uint8_t(value >> shift));
}

std::vector<std::uint8_t> makeChunk(const char type[4], const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> chunk;
  chunk.reserve(data.size() + 12);
  putBigEndian(chunk, std::uint32_t(data.size()));
  chunk.insert(chunk.end(), type, type + 4);
  chunk.insert(chunk.end(), data.begin(), data.end());
  const uLong crc = crc32(0, chunk.data() + 4, uInt(data.size() + 4));
  putBigEndian(chunk, std::uint32_t(crc));
  return chunk;
}

// Noise in [-0.5, 0.5) from the texel's position (a fixed hash, so saves are reproducible).
float ditherNoise(std::uint32_t x, std::uint32_t y, std::uint32_t channel) {
  std::uint32_t h = x * 0x9E3779B1u ^ (y + 0x7F4A7C15u) * 0x85EBCA77u ^ channel * 0xC2B2AE3Du;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return float(h >> 8) * (1.0f / 16777216.0f) - 0.5f;
}

// One row as PNG samples: big-endian for 16 bits.
void convertRow(const Image& image, int y, const PngWriteOptions& options, std::uint8_t* out) {
  const float* source = image.pixel(0, y);
  const int values = image.width() * image.channels();
  if (options.bitsPerChannel == 16) {
    for (int i = 0; i < values; ++i) {
      const auto q = std::uint32_t(std::clamp(source[i], 0.0f, 1.0f) * 65535.0f + 0.5f);
      out[2 * i] = std::uint8_t(q >> 8);
      out[2 * i + 1] = std::uint8_t(q);
    }
    return;
  }
  for (int i = 0; i < values; ++i) {
    float scaled = std::clamp(source[i], 0.0f, 1.0f) * 255.0f;
    if (options.dither) {
      const int x = i / image.channels(), channel = i % image.channels();
      scaled += ditherNoise(std::uint32_t(x), std::uint32_t(y), std::uint32_t(channel));
    }
    out[i] = std::uint8_t(std::clamp(scaled + 0.5f, 0.0f, 255.0f));
  }
}

// Paeth-filtered row (filter byte first): each byte less its predictor from the byte to the
// left (a), above (b) and above-left (c). Written without branches so that it vectorises.
void paethRow(const std::uint8_t* row, const std::uint8_t* above, int bytesPerPixel,
              std::size_t rowBytes, std::uint8_t* out) {
  out[0] = kPaethFilter;
  for (std::size_t i = 0; i < rowBytes; ++i) {
    const bool hasLeft = i >= std::size_t(bytesPerPixel);
    const int a = hasLeft ? row[i - std::size_t(bytesPerPixel)] : 0;
    const int b = above[i];
    const int c = hasLeft ? above[i - std::size_t(bytesPerPixel)] : 0;
    const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    const int predictor = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
    out[i + 1] = std::uint8_t(row[i] - predictor);
  }
}

// One strip of rows, filtered and deflated: the payload of one IDAT chunk.
struct Strip {
  // Deflate's output, with room for the stream's Adler-32 after the last strip. Raw arrays,
  // not vectors: zeroing deflateBound's worst case first cost 5% of a 4096^2 save.
  std::unique_ptr<std::uint8_t[]> payload;
  std::size_t payloadSize = 0;
  uLong adler = 1;           // of the filtered bytes
  std::size_t filtered = 0;  // their count
  uLong crc = 0;             // of "IDAT" and the payload
  bool ok = false;
};

// Strip `s` of the image (rows first..last): converted, Paeth-filtered and deflated on its own.
// Raw deflate; every strip but the last ends on a byte boundary (sync flush) so the streams join
// into one, the last one finishes it. The zlib header goes before strip 0 and the combined
// Adler-32 after the last (appendAdler32).
void compressStrip(const Image& image, const PngWriteOptions& options, int s, int stripCount,
                   int rowsPerStrip, std::size_t rowBytes, int bytesPerPixel, Strip& strip) {
  const int first = s * rowsPerStrip, last = std::min(first + rowsPerStrip, image.height());
  std::vector<std::uint8_t> above(rowBytes, 0), row(rowBytes);
  if (first > 0)
    convertRow(image, first - 1, options, above.data());
  strip.filtered = std::size_t(last - first) * (rowBytes + 1);
  const std::unique_ptr<std::uint8_t[]> filtered(new std::uint8_t[strip.filtered]);
  for (int y = first; y < last; ++y) {
    convertRow(image, y, options, row.data());
    paethRow(row.data(), above.data(), bytesPerPixel, rowBytes,
             filtered.get() + std::size_t(y - first) * (rowBytes + 1));
    std::swap(row, above);
  }
  strip.adler = adler32(1, filtered.get(), uInt(strip.filtered));
  z_stream stream{};
  if (deflateInit2(&stream, 1, Z_DEFLATED, -15, 8, Z_RLE) != Z_OK)
    return;
  const bool lastStrip = s == stripCount - 1;
  const std::size_t header = s == 0 ? 2 : 0;
  const std::size_t capacity = header + deflateBound(&stream, uLong(strip.filtered)) + 16;
  strip.payload.reset(new std::uint8_t[capacity + 4]);  // + 4: the Adler-32 at the end
  if (s == 0) {
    strip.payload[0] = 0x78;  // deflate, 32 KiB window
    strip.payload[1] = 0x01;  // fastest level; (0x78 * 256 + 0x01) is a multiple of 31
  }
  stream.next_in = filtered.get();
  stream.avail_in = uInt(strip.filtered);
  stream.next_out = strip.payload.get() + header;
  stream.avail_out = uInt(capacity - header);
  const int result = deflate(&stream, lastStrip ? Z_FINISH : Z_SYNC_FLUSH);
  const bool complete =
      lastStrip ? result == Z_STREAM_END : (result == Z_OK && stream.avail_in == 0);
  strip.payloadSize = capacity - stream.avail_out;
  deflateEnd(&stream);
  const char type[4] = {'I', 'D', 'A', 'T'};
  strip.crc = crc32(crc32(0, reinterpret_cast<const Bytef*>(type), 4), strip.payload.get(),
                    uInt(strip.payloadSize));
  strip.ok = complete;
}

// The zlib stream's Adler-32 of all filtered bytes, from the strips' own, after the last
// strip's payload (its room was reserved).
void appendAdler32(std::vector<Strip>& strips) {
  uLong adler = strips[0].adler;
  for (std::size_t s = 1; s < strips.size(); ++s)
    adler = adler32_combine(adler, strips[s].adler, z_off_t(strips[s].filtered));
  Strip& lastStrip = strips.back();
  std::vector<std::uint8_t> adlerBytes;
  putBigEndian(adlerBytes, std::uint32_t(adler));
  std::copy(adlerBytes.begin(), adlerBytes.end(), lastStrip.payload.get() + lastStrip.payloadSize);
  lastStrip.payloadSize += 4;
  lastStrip.crc = crc32(lastStrip.crc, adlerBytes.data(), 4);
}

// The chunks before the image data: size and sample layout, then how to read the colours.
std::vector<std::vector<std::uint8_t>> headerChunks(const Image& image,
                                                    const PngWriteOptions& options) {
  std::vector<std::uint8_t> ihdr;
  putBigEndian(ihdr, std::uint32_t(image.width()));
  putBigEndian(ihdr, std::uint32_t(image.height()));
  constexpr std::array<std::uint8_t, 5> kColourType = {0, 0, 4, 2, 6};  // by channel count
  ihdr.insert(ihdr.end(), {std::uint8_t(options.bitsPerChannel),
                           kColourType[std::size_t(image.channels())], 0, 0, 0});
  std::vector<std::vector<std::uint8_t>> headers = {makeChunk("IHDR", ihdr)};
  const bool srgb = image.colorSpace() == ColorSpace::Srgb;
  std::vector<std::uint8_t> gamma;
  putBigEndian(gamma, srgb ? 45455u : 100000u);  // 1/2.2 or 1.0, times 100000
  if (srgb) {
    headers.push_back(makeChunk("sRGB", {0}));  // perceptual intent
    headers.push_back(makeChunk("gAMA", gamma));
    std::vector<std::uint8_t> chromaticities;  // Rec. 709 primaries, D65 white, times 100000
    for (std::uint32_t value : {31270u, 32900u, 64000u, 33000u, 30000u, 60000u, 15000u, 6000u})
      putBigEndian(chromaticities, value);
    headers.push_back(makeChunk("cHRM", chromaticities));
  } else {
    headers.push_back(makeChunk("gAMA", gamma));
  }
  const std::string text = std::string("oiio:ColorSpace") + '\0' + (srgb ? "sRGB" : "Linear");
  headers.push_back(makeChunk("tEXt", std::vector<std::uint8_t>(text.begin(), text.end())));
  return headers;
}

}  // namespace

Status writePng(const Image& image, const std::string& path, const PngWriteOptions& options) {
  if (image.isEmpty() || image.channels() < 1 || image.channels() > 4)
    return makeError(path + ": cannot write a PNG of " + std::to_string(image.channels()) +
                     " channels");
  const int bytesPerSample = options.bitsPerChannel == 16 ? 2 : 1;
  const int bytesPerPixel = bytesPerSample * image.channels();
  const std::size_t rowBytes = std::size_t(image.width()) * std::size_t(bytesPerPixel);
  const int rowsPerStrip = int(std::max<std::size_t>(1, kStripBytes / (rowBytes + 1)));
  const int stripCount = (image.height() + rowsPerStrip - 1) / rowsPerStrip;
  std::vector<Strip> strips(static_cast<std::size_t>(stripCount));

  parallelFor(stripCount, [&](int s) {
    compressStrip(image, options, s, stripCount, rowsPerStrip, rowBytes, bytesPerPixel,
                  strips[std::size_t(s)]);
  });
  for (const Strip& strip : strips) {
    if (!strip.ok)
      return makeError(path + ": cannot write (zlib could not compress the image)");
  }
  appendAdler32(strips);
  const std::vector<std::vector<std::uint8_t>> headers = headerChunks(image, options);

  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"),
                                                       &std::fclose);
  const auto failed = [&path] {
    return makeError(path + ": cannot write (" + std::strerror(errno) + ")");
  };
  if (!file)
    return failed();
  const auto write = [&file](const void* data, std::size_t size) {
    return std::fwrite(data, 1, size, file.get()) == size;
  };
  constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  bool ok = write(kSignature, sizeof kSignature);
  for (const auto& chunk : headers)
    ok = ok && write(chunk.data(), chunk.size());
  for (const Strip& strip : strips) {
    std::vector<std::uint8_t> head;
    putBigEndian(head, std::uint32_t(strip.payloadSize));
    head.insert(head.end(), {'I', 'D', 'A', 'T'});
    std::vector<std::uint8_t> tail;
    putBigEndian(tail, std::uint32_t(strip.crc));
    ok = ok && write(head.data(), head.size()) && write(strip.payload.get(), strip.payloadSize) &&
         write(tail.data(), tail.size());
  }
  const std::vector<std::uint8_t> end = makeChunk("IEND", {});
  ok = ok && write(end.data(), end.size()) && std::fflush(file.get()) == 0;
  if (!ok)
    return failed();
  if (std::fclose(file.release()) != 0)
    return failed();
  return {};
}

}  // namespace relief::core::inline image
