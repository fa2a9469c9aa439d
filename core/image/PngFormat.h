// What Relief's PNG code (PngPreflight, PngReader, PngVerify) shares: the signature, big-endian
// fields, the colour types' samples and bit depths, row filters and Adam7's passes, as the PNG
// specification (ISO/IEC 15948, third edition) defines them. Internal to core/image.
#pragma once

#include "core/base/Result.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace relief::core::inline image::png {

// The reader's and the verifier's one message for pixel data that does not inflate or unfilter.
inline Error damagedPixelData(const std::string& path, const std::string& what) {
  return makeError(path + ": the pixel data is damaged or truncated (" + what + ")");
}

inline constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

inline std::uint32_t bigEndian32(const std::uint8_t* bytes) {
  return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 |
         std::uint32_t(bytes[2]) << 8 | std::uint32_t(bytes[3]);
}

// Samples per pixel as stored (section 6.1), 0 for reserved types.
inline int storedSamplesOf(int colourType) {
  switch (colourType) {
    case 0:
      return 1;  // grey
    case 3:
      return 1;  // palette index
    case 4:
      return 2;  // grey and alpha
    case 2:
      return 3;  // RGB
    case 6:
      return 4;  // RGBA
    default:
      return 0;
  }
}

// The bit depths each colour type allows (section 11.2.2, table 11.1).
inline bool allowedDepth(int colourType, int bitDepth) {
  switch (colourType) {
    case 0:
      return bitDepth == 1 || bitDepth == 2 || bitDepth == 4 || bitDepth == 8 || bitDepth == 16;
    case 3:
      return bitDepth == 1 || bitDepth == 2 || bitDepth == 4 || bitDepth == 8;
    case 2:
    case 4:
    case 6:
      return bitDepth == 8 || bitDepth == 16;
    default:
      return false;
  }
}

// Bytes of one row of `width` pixels as stored, without its filter byte.
inline std::size_t rowBytesOf(std::uint32_t width, int bitDepth, int colourType) {
  const std::size_t bits = std::size_t(bitDepth) * std::size_t(storedSamplesOf(colourType));
  return (bits * width + 7) / 8;
}

// The filters' "bytes per complete pixel", at least one (section 9.2).
inline std::size_t filterStride(int bitDepth, int colourType) {
  const std::size_t bits = std::size_t(bitDepth) * std::size_t(storedSamplesOf(colourType));
  return bits < 8 ? 1 : bits / 8;
}

// Undoes one row's filter in place (section 9.2). `above` is the previous unfiltered row of the
// same (sub-)image, or null for its first row, whose "above" bytes are zero. False for an unknown
// filter type.
inline bool unfilterRow(std::uint8_t filter, std::uint8_t* row, const std::uint8_t* above,
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
      if (!above) {
        for (std::size_t i = bytesPerPixel; i < rowBytes; ++i)
          row[i] = std::uint8_t(row[i] + (row[i - bytesPerPixel] >> 1));
        return true;
      }
      for (std::size_t i = 0; i < std::min(bytesPerPixel, rowBytes); ++i)
        row[i] = std::uint8_t(row[i] + (above[i] >> 1));
      for (std::size_t i = bytesPerPixel; i < rowBytes; ++i)
        row[i] = std::uint8_t(row[i] + ((row[i - bytesPerPixel] + above[i]) >> 1));
      return true;
    case 4:  // Paeth
      // The first pixel (no left, no upper left) predicts from above; the first row (no above)
      // from the left, as Sub. The rest without branches: photographs' predictors change from
      // byte to byte, and the mispredicted branches took 2.4 times as long (47 ms against 20 on
      // a 2048x2048 RGB photograph).
      if (!above) {
        for (std::size_t i = bytesPerPixel; i < rowBytes; ++i)
          row[i] = std::uint8_t(row[i] + row[i - bytesPerPixel]);
        return true;
      }
      for (std::size_t i = 0; i < std::min(bytesPerPixel, rowBytes); ++i)
        row[i] = std::uint8_t(row[i] + above[i]);
      for (std::size_t i = bytesPerPixel; i < rowBytes; ++i) {
        const int a = row[i - bytesPerPixel], b = above[i], c = above[i - bytesPerPixel];
        const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
        const int nearerOfAB = pa <= pb ? a : b;
        const int distanceAB = pa <= pb ? pa : pb;
        row[i] = std::uint8_t(row[i] + (distanceAB <= pc ? nearerOfAB : c));
      }
      return true;
    default:
      return false;
  }
}

// One of the sub-images a PNG stores: the whole image, or one of Adam7's seven passes
// (section 8.2): pixels x = xStart + i * xStep, y = yStart + j * yStep.
struct PngPass {
  std::uint32_t xStart, yStart, xStep, yStep;
  std::uint32_t width, height;  // 0 when the pass holds no pixel of this image
};

inline PngPass adam7Pass(int pass, std::uint32_t width, std::uint32_t height) {
  static constexpr std::uint32_t kStart[7][2] = {{0, 0}, {4, 0}, {0, 4}, {2, 0},
                                                 {0, 2}, {1, 0}, {0, 1}};
  static constexpr std::uint32_t kStep[7][2] = {{8, 8}, {8, 8}, {4, 8}, {4, 4},
                                                {2, 4}, {2, 2}, {1, 2}};
  PngPass p{kStart[pass][0], kStart[pass][1], kStep[pass][0], kStep[pass][1], 0, 0};
  if (width > p.xStart && height > p.yStart) {
    p.width = (width - p.xStart + p.xStep - 1) / p.xStep;
    p.height = (height - p.yStart + p.yStep - 1) / p.yStep;
  }
  return p;
}

// The sub-images a PNG with this interlace method stores, in order: one, or Adam7's seven.
inline int passCount(int interlace) {
  return interlace == 1 ? 7 : 1;
}

inline PngPass passOf(int interlace, int pass, std::uint32_t width, std::uint32_t height) {
  return interlace == 1 ? adam7Pass(pass, width, height) : PngPass{0, 0, 1, 1, width, height};
}

}  // namespace relief::core::inline image::png
