// BC1-BC5 and DXT5nm blocks; see BlockCodecs.h. The decoder follows the D3D10 block formats
// (also EXT_texture_compression_s3tc and ARB_texture_compression_rgtc): BC1 colour endpoints
// are RGB 5:6:5 with bit replication, c0 > c1 selects four colours, otherwise three and
// transparent black (BC2/BC3 colour blocks always use four); BC3 alpha and BC4/BC5 channels
// interpolate 8 values when a0 > a1, else 6 plus 0 and 1.
#include "core/compression/Bc6hBlock.h"
#include "core/compression/Bc7Block.h"
#include "core/compression/BlockCodecs.h"
#include "core/image/HalfFloat.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace relief::core::inline compression {
namespace {

std::uint16_t read16(const std::uint8_t* p) {
  return std::uint16_t(p[0] | p[1] << 8);
}

// The colour half of BC1/BC2/BC3.
void decodeColour(const std::uint8_t* in, bool bc1, BlockTexels& texels) {
  const std::uint16_t c0 = read16(in), c1 = read16(in + 2);
  float palette[4][4];
  for (int e = 0; e < 2; ++e) {
    const std::uint16_t c = e == 0 ? c0 : c1;
    const int r = (c >> 11) & 31, g = (c >> 5) & 63, b = c & 31;
    palette[e][0] = float((r << 3) | (r >> 2));
    palette[e][1] = float((g << 2) | (g >> 4));
    palette[e][2] = float((b << 3) | (b >> 2));
    palette[e][3] = 255.0f;
  }
  const bool fourColours = !bc1 || c0 > c1;
  for (int ch = 0; ch < 3; ++ch) {
    if (fourColours) {
      palette[2][ch] = std::floor((2.0f * palette[0][ch] + palette[1][ch]) / 3.0f);
      palette[3][ch] = std::floor((palette[0][ch] + 2.0f * palette[1][ch]) / 3.0f);
    } else {
      palette[2][ch] = std::floor((palette[0][ch] + palette[1][ch]) / 2.0f);
      palette[3][ch] = 0.0f;
    }
  }
  palette[2][3] = 255.0f;
  palette[3][3] = fourColours ? 255.0f : 0.0f;
  for (int t = 0; t < 16; ++t) {
    const int index = (in[4 + t / 4] >> (2 * (t % 4))) & 3;
    for (int ch = 0; ch < 4; ++ch)
      texels[t][ch] = palette[index][ch] / 255.0f;
  }
}

// One BC4 channel block (also BC3's alpha and each BC5 channel).
void decodeChannel(const std::uint8_t* in, BlockTexels& texels, int channel) {
  const float a0 = in[0], a1 = in[1];
  float values[8] = {a0, a1};
  if (a0 > a1) {
    for (int i = 1; i <= 6; ++i)
      values[i + 1] = ((7 - i) * a0 + i * a1) / 7.0f;
  } else {
    for (int i = 1; i <= 4; ++i)
      values[i + 1] = ((5 - i) * a0 + i * a1) / 5.0f;
    values[6] = 0.0f;
    values[7] = 255.0f;
  }
  std::uint64_t bits = 0;
  for (int i = 0; i < 6; ++i)
    bits |= std::uint64_t(in[2 + i]) << (8 * i);
  // Decoders disagree in the last bit here (D3D10 interpolates in float; Mesa in integers,
  // rounding down); rounding to the nearest 8-bit value keeps us within one step of both.
  for (int t = 0; t < 16; ++t)
    texels[t][channel] = std::round(values[(bits >> (3 * t)) & 7]) / 255.0f;
}

// Values the eight-value mode (a0 > a1) decodes to for index 0..7, rounded as decodeChannel.
void paletteOf(int a0, int a1, int palette[8]) {
  palette[0] = a0;
  palette[1] = a1;
  for (int i = 1; i <= 6; ++i)
    palette[i + 1] = int(std::lround(((7 - i) * a0 + i * a1) / 7.0));
}

// Indices for the eight-value palette, nearest value for each texel; returns the squared error
// over the valid texels.
int fitIndices(const float values[16], int validMask, int a0, int a1, int indices[16]) {
  int palette[8];
  paletteOf(a0, a1, palette);
  // Palette order from a1 (low) up to a0 (high) is index 1, 7, 6, 5, 4, 3, 2, 0.
  static constexpr int kByLevel[8] = {1, 7, 6, 5, 4, 3, 2, 0};
  int error = 0;
  const float scale = a0 > a1 ? 7.0f / float(a0 - a1) : 0.0f;
  for (int t = 0; t < 16; ++t) {
    // The nearest level by arithmetic, then its neighbours (palette rounding can shift it).
    const int guess = std::clamp(int((values[t] - float(a1)) * scale + 0.5f), 0, 7);
    int best = kByLevel[guess];
    float bestError = std::abs(values[t] - float(palette[best]));
    for (int level : {guess - 1, guess + 1}) {
      if (level < 0 || level > 7)
        continue;
      const float e = std::abs(values[t] - float(palette[kByLevel[level]]));
      if (e < bestError) {
        bestError = e;
        best = kByLevel[level];
      }
    }
    indices[t] = best;
    if (validMask & (1 << t)) {
      const int d = int(values[t] + 0.5f) - palette[best];
      error += d * d;
    }
  }
  return error;
}

void writeChannelBlock(int a0, int a1, const int indices[16], std::uint8_t* out) {
  out[0] = std::uint8_t(a0);
  out[1] = std::uint8_t(a1);
  std::uint64_t bits = 0;
  for (int t = 0; t < 16; ++t)
    bits |= std::uint64_t(indices[t]) << (3 * t);
  for (int i = 0; i < 6; ++i)
    out[2 + i] = std::uint8_t(bits >> (8 * i));
}

// One BC4 channel block, written here rather than with libsquish: squish's BC4/BC5 encoder
// (CompressAlphaDxt5 per channel) takes 1.2 s for a 4096^2 BC5 map on this machine's two cores,
// over the 1 s target, while this one fits the same eight-value palette between the block's
// extremes (what squish's range fit does) in a fraction of that, and then refines the endpoints
// by least squares over the chosen indices (1, 2 or 4 passes for fast, normal, best), which
// squish does not.
// `values` are 0..255.
void encodeChannelBlock(const float values[16], int validMask, CompressionQuality quality,
                        std::uint8_t* out) {
  float low = 255.0f, high = 0.0f;
  for (int t = 0; t < 16; ++t) {
    if (validMask & (1 << t)) {
      low = std::min(low, values[t]);
      high = std::max(high, values[t]);
    }
  }
  if (validMask == 0)
    low = high = 0.0f;
  int a0 = int(std::lround(high)), a1 = int(std::lround(low));
  int indices[16];
  if (a0 == a1) {
    // A flat block: a0 > a1 is needed for the eight-value mode; any index 0 gives a0.
    std::fill(indices, indices + 16, 0);
    if (a0 == 0) {
      a0 = 1;
      std::fill(indices, indices + 16, 1);  // a1 = 0
    } else {
      a1 = a0 - 1;
    }
    writeChannelBlock(a0, a1, indices, out);
    return;
  }
  int error = fitIndices(values, validMask, a0, a1, indices);
  const int passes = quality == CompressionQuality::Fast     ? 1
                     : quality == CompressionQuality::Normal ? 2
                                                             : 4;
  for (int pass = 0; pass < passes && error > 0; ++pass) {
    // Least squares for the endpoints given each texel's weight w (value = a1 + w (a0 - a1)).
    static constexpr float kWeight[8] = {1.0f,     0.0f,     6 / 7.0f, 5 / 7.0f,
                                         4 / 7.0f, 3 / 7.0f, 2 / 7.0f, 1 / 7.0f};
    double ww = 0, w1 = 0, n = 0, wv = 0, v = 0;
    for (int t = 0; t < 16; ++t) {
      if (!(validMask & (1 << t)))
        continue;
      const double w = kWeight[indices[t]];
      ww += w * w;
      w1 += w;
      n += 1;
      wv += w * values[t];
      v += values[t];
    }
    // Solve for (d = a0 - a1, b = a1): [ww w1; w1 n] [d; b] = [wv; v].
    const double det = ww * n - w1 * w1;
    if (std::abs(det) < 1e-9)
      break;
    const double d = (n * wv - w1 * v) / det, b = (ww * v - w1 * wv) / det;
    const int c0 = std::clamp(int(std::lround(b + d)), 0, 255);
    const int c1 = std::clamp(int(std::lround(b)), 0, 255);
    if (c0 <= c1 || (c0 == a0 && c1 == a1))
      break;
    int candidate[16];
    const int candidateError = fitIndices(values, validMask, c0, c1, candidate);
    if (candidateError >= error)
      break;
    error = candidateError;
    a0 = c0;
    a1 = c1;
    std::copy(candidate, candidate + 16, indices);
  }
  writeChannelBlock(a0, a1, indices, out);
}

}  // namespace

void encodeBcBlock(TextureFormat format, CompressionQuality quality, bool perceptual,
                   const BlockTexels& texels, int validMask, std::uint8_t* out) {
  if (format == TextureFormat::Bc7) {
    encodeBc7Block(quality, texels, validMask, out);
    return;
  }
  if (isHalfFloatFormat(format)) {
    encodeBc6hBlock(format == TextureFormat::Bc6hSigned, quality, texels, validMask, out);
    return;
  }
  if (format == TextureFormat::Bc4 || format == TextureFormat::Bc5) {
    float values[16];
    for (int ch = 0; ch < (format == TextureFormat::Bc5 ? 2 : 1); ++ch) {
      for (int t = 0; t < 16; ++t)
        values[t] = std::clamp(texels[t][ch], 0.0f, 1.0f) * 255.0f;
      encodeChannelBlock(values, validMask, quality, out + 8 * ch);
    }
    return;
  }
  // The alpha half: BC2's explicit 4-bit values, BC3's (and DXT5nm's) a BC4 channel block.
  if (format == TextureFormat::Bc2) {
    for (int t = 0; t < 16; t += 2) {
      const int a0 = int(std::lround(std::clamp(texels[t][3], 0.0f, 1.0f) * 15.0f));
      const int a1 = int(std::lround(std::clamp(texels[t + 1][3], 0.0f, 1.0f) * 15.0f));
      out[t / 2] = std::uint8_t(a0 | a1 << 4);
    }
  } else if (format == TextureFormat::Bc3 || format == TextureFormat::Dxt5nm) {
    // DXT5nm stores normal X in alpha (and Y in green below).
    const int source = format == TextureFormat::Dxt5nm ? 0 : 3;
    float values[16];
    for (int t = 0; t < 16; ++t)
      values[t] = std::clamp(texels[t][source], 0.0f, 1.0f) * 255.0f;
    encodeChannelBlock(values, validMask, quality, out);
  } else if (format != TextureFormat::Bc1) {
    throwNotOfFamily("encodeBcBlock", format);
  }
  // The colour half. DXT5nm's red and blue carry nothing, so the fit spends everything on
  // green.
  float rgb[16][3];
  for (int t = 0; t < 16; ++t) {
    for (int ch = 0; ch < 3; ++ch)
      rgb[t][ch] = std::clamp(texels[t][ch], 0.0f, 1.0f) * 255.0f;
    if (format == TextureFormat::Dxt5nm)
      rgb[t][0] = rgb[t][2] = 0.0f;
  }
  const bool bc1 = format == TextureFormat::Bc1;
  encodeBc1Colour(rgb, validMask, quality, perceptual && format != TextureFormat::Dxt5nm, bc1,
                  bc1 ? out : out + 8);
}

void decodeBcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels) {
  if (format == TextureFormat::Bc1) {
    decodeColour(in, true, texels);
  } else if (format == TextureFormat::Bc2) {
    decodeColour(in + 8, false, texels);
    for (int t = 0; t < 16; ++t)
      texels[t][3] = float((in[t / 2] >> (4 * (t % 2))) & 15) * 17.0f / 255.0f;
  } else if (format == TextureFormat::Bc3 || format == TextureFormat::Dxt5nm) {
    decodeColour(in + 8, false, texels);
    decodeChannel(in, texels, 3);
  } else if (format == TextureFormat::Bc4) {
    decodeChannel(in, texels, 0);
    for (int t = 0; t < 16; ++t) {
      texels[t][1] = texels[t][2] = 0.0f;
      texels[t][3] = 1.0f;
    }
  } else if (format == TextureFormat::Bc5) {
    decodeChannel(in, texels, 0);
    decodeChannel(in + 8, texels, 1);
    for (int t = 0; t < 16; ++t) {
      texels[t][2] = 0.0f;
      texels[t][3] = 1.0f;
    }
  } else if (format == TextureFormat::Bc7) {
    std::uint8_t rgba[16][4];
    decodeBc7Block(in, rgba);
    for (int t = 0; t < 16; ++t) {
      for (int ch = 0; ch < 4; ++ch)
        texels[t][ch] = float(rgba[t][ch]) / 255.0f;
    }
  } else if (isHalfFloatFormat(format)) {
    std::uint16_t halves[16][3];
    decodeBc6hBlock(in, format == TextureFormat::Bc6hSigned, halves);
    for (int t = 0; t < 16; ++t) {
      for (int ch = 0; ch < 3; ++ch)
        texels[t][ch] = halfToFloat(halves[t][ch]);
      texels[t][3] = 1.0f;
    }
  } else {
    throwNotOfFamily("decodeBcBlock", format);
  }
}

void throwNotOfFamily(const char* codec, TextureFormat format) {
  throw std::logic_error(std::string(codec) + ": " + std::string(textureFormatInfo(format).name) +
                         " is not a format this codec knows");
}

}  // namespace relief::core::inline compression
