// BC1-BC5 and DXT5nm blocks; see BlockCodecs.h. The decoder follows the D3D10 block formats
// (also EXT_texture_compression_s3tc and ARB_texture_compression_rgtc): BC1 colour endpoints
// are RGB 5:6:5 with bit replication, c0 > c1 selects four colours, otherwise three and
// transparent black (BC2/BC3 colour blocks always use four); BC3 alpha and BC4/BC5 channels
// interpolate 8 values when a0 > a1, else 6 plus 0 and 1.
#include "core/compression/BlockCodecs.h"

#include <squish.h>

#include <algorithm>
#include <cmath>

namespace relief::core {
namespace {

std::uint8_t toByte(float value) {
  return std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

int squishFit(CompressionQuality quality) {
  switch (quality) {
    case CompressionQuality::Fast:
      return squish::kColourRangeFit;
    case CompressionQuality::Normal:
      return squish::kColourClusterFit;
    case CompressionQuality::Best:
      return squish::kColourIterativeClusterFit;
  }
  return squish::kColourClusterFit;
}

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

}  // namespace

void encodeBcBlock(TextureFormat format, CompressionQuality quality, bool perceptual,
                   const BlockTexels& texels, int validMask, std::uint8_t* out) {
  squish::u8 rgba[16 * 4];
  for (int t = 0; t < 16; ++t) {
    for (int ch = 0; ch < 4; ++ch)
      rgba[t * 4 + ch] = toByte(texels[t][ch]);
    if (format == TextureFormat::Dxt5nm) {
      // X to alpha, Y stays in green; red and blue carry nothing, so the colour fit spends
      // everything on green.
      rgba[t * 4 + 3] = rgba[t * 4 + 0];
      rgba[t * 4 + 0] = 0;
      rgba[t * 4 + 2] = 0;
    }
  }
  int flags = squishFit(quality);
  // libsquish 1.15 takes the metric as channel weights; null is uniform.
  float perceptualWeights[3] = {0.2126f, 0.7152f, 0.0722f};
  float* metric = perceptual && format != TextureFormat::Dxt5nm ? perceptualWeights : nullptr;
  switch (format) {
    case TextureFormat::Bc1:
      flags |= squish::kDxt1;
      // kDxt1 turns alpha < 128 into transparent black (PLATFORM.md): BC1 here is opaque.
      for (int t = 0; t < 16; ++t)
        rgba[t * 4 + 3] = 255;
      break;
    case TextureFormat::Bc2:
      flags |= squish::kDxt3;
      break;
    case TextureFormat::Bc3:
    case TextureFormat::Dxt5nm:
      flags |= squish::kDxt5;
      break;
    case TextureFormat::Bc4:
      flags |= squish::kBc4;
      break;
    case TextureFormat::Bc5:
      flags |= squish::kBc5;
      break;
    default:
      return;
  }
  squish::CompressMasked(rgba, validMask, out, flags, metric);
}

void decodeBcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels) {
  switch (format) {
    case TextureFormat::Bc1:
      decodeColour(in, true, texels);
      return;
    case TextureFormat::Bc2:
      decodeColour(in + 8, false, texels);
      for (int t = 0; t < 16; ++t)
        texels[t][3] = float((in[t / 2] >> (4 * (t % 2))) & 15) * 17.0f / 255.0f;
      return;
    case TextureFormat::Bc3:
    case TextureFormat::Dxt5nm:
      decodeColour(in + 8, false, texels);
      decodeChannel(in, texels, 3);
      return;
    case TextureFormat::Bc4:
      decodeChannel(in, texels, 0);
      for (int t = 0; t < 16; ++t) {
        texels[t][1] = texels[t][2] = 0.0f;
        texels[t][3] = 1.0f;
      }
      return;
    case TextureFormat::Bc5:
      decodeChannel(in, texels, 0);
      decodeChannel(in + 8, texels, 1);
      for (int t = 0; t < 16; ++t) {
        texels[t][2] = 0.0f;
        texels[t][3] = 1.0f;
      }
      return;
    default:
      return;
  }
}

}  // namespace relief::core
