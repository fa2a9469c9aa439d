// BC6H (BPTC float): the block layer against hand-worked blocks from the specification
// (ARB_texture_compression_bptc, "BPTC float"), the encoder on HDR content, the clamping of
// values half floats cannot hold, and the exposure PSNR and log error HDR maps are judged by.
// The decoder is checked against llvmpipe's independent one in CompressedSamplingTest.
#include "core/compression/Bc6hBlock.h"
#include "core/compression/BlockCodecs.h"
#include "core/compression/CompressionJob.h"
#include "core/compression/CompressionMetrics.h"
#include "core/compression/Compressor.h"
#include "core/compression/TextureFile.h"
#include "core/image/HalfFloat.h"
#include "core/shading/EnvironmentMaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace relief::test {
namespace {

using core::TextureFormat;

// The spec's two-bit mode numbers are 0 and 1; the rest are five bits.
void setModeBits(std::uint8_t block[16], int code) {
  block[0] = std::uint8_t(code < 2 ? (block[0] & ~3) | code : (block[0] & ~31) | code);
}

// Bits [first, first + count) of a block set to `value`, least significant bit first.
void setBits(std::uint8_t block[16], int first, int count, int value) {
  for (int i = 0; i < count; ++i) {
    const int position = first + i;
    block[position >> 3] = std::uint8_t((block[position >> 3] & ~(1 << (position & 7))) |
                                        ((value >> i) & 1) << (position & 7));
  }
}

TEST(Bc6h, HalfConversionsRoundToNearestEven) {
  EXPECT_EQ(core::floatToHalf(1.0f), 0x3C00);
  EXPECT_EQ(core::floatToHalf(-2.0f), 0xC000);
  EXPECT_EQ(core::floatToHalf(65504.0f), 0x7BFF);
  EXPECT_EQ(core::floatToHalf(65520.0f), 0x7C00);           // the first value rounding to infinity
  EXPECT_EQ(core::floatToHalf(std::exp2(-24.0f)), 0x0001);  // the smallest subnormal
  // 1 + 2^-11 lies halfway between 1 and 1 + 2^-10: ties go to the even mantissa (1).
  EXPECT_EQ(core::floatToHalf(1.0f + std::exp2(-11.0f)), 0x3C00);
  EXPECT_EQ(core::floatToHalf(1.0f + 3.0f * std::exp2(-11.0f)), 0x3C02);
  for (int bits = 0; bits < 0x7C00; bits += 7)
    EXPECT_EQ(core::floatToHalf(core::halfToFloat(std::uint16_t(bits))), bits);
}

// Unpacking then packing any block of a valid mode gives its bytes back: the layout tables
// cover every header bit exactly once and the indices follow at bit 82 (two subsets) or 65.
TEST(Bc6h, EveryModeUnpacksAndPacksBackBitForBit) {
  std::mt19937 random(7);
  for (const core::Bc6hMode& mode : core::kBc6hModes) {
    for (int copy = 0; copy < 64; ++copy) {
      std::uint8_t in[16], out[16];
      for (std::uint8_t& byte : in)
        byte = std::uint8_t(random());
      setModeBits(in, mode.code);
      core::Bc6hBlock block;
      ASSERT_TRUE(core::unpackBc6hBlock(in, block)) << "mode " << mode.code;
      EXPECT_EQ(core::kBc6hModes[block.mode].code, mode.code);
      core::packBc6hBlock(block, out);
      for (int i = 0; i < 16; ++i)
        ASSERT_EQ(out[i], in[i]) << "mode " << mode.code << " byte " << i;
    }
  }
}

TEST(Bc6h, ReservedModesDecodeToBlack) {
  for (int code : {19, 23, 27, 31}) {
    std::uint8_t block[16];
    for (std::uint8_t& byte : block)
      byte = 0xA5;
    setModeBits(block, code);
    std::uint16_t halves[16][3];
    core::decodeBc6hBlock(block, false, halves);
    for (const auto& texel : halves)
      EXPECT_EQ(texel[0] | texel[1] | texel[2], 0) << "mode " << code;
  }
}

// Mode 3 (code 3): one subset, 10-bit endpoints stored as they are; the header is the mode,
// then r0, g0, b0, r1, g1, b1 (10 bits each), then 4-bit indices (texel 0: 3 bits).
TEST(Bc6h, HandWorkedUnsignedBlockDecodes) {
  std::uint8_t block[16] = {};
  setModeBits(block, 3);
  for (int c = 0; c < 3; ++c) {
    setBits(block, 5 + 10 * c, 10, 0);      // e0 = 0: unquantises to 0
    setBits(block, 35 + 10 * c, 10, 1023);  // e1 = 1023, the top: unquantises to 0xFFFF
  }
  // Texel 1 index 8 (weight 34), texel 15 index 15 (weight 64), the rest 0.
  setBits(block, 65 + 3 + 4 * 0, 4, 8);
  setBits(block, 65 + 3 + 4 * 14, 4, 15);
  std::uint16_t halves[16][3];
  core::decodeBc6hBlock(block, false, halves);
  // Index 8: (34 * 65535 + 32) >> 6 = 34815; x 31 >> 6 = 16863 = 0x41DF (2.9355...).
  EXPECT_EQ(halves[1][0], 0x41DF);
  EXPECT_FLOAT_EQ(core::halfToFloat(halves[1][1]), 2.935546875f);
  // Index 15: 65535 x 31 >> 6 = 31743 = 0x7BFF, the largest half.
  EXPECT_EQ(halves[15][2], 0x7BFF);
  EXPECT_EQ(halves[0][0], 0);
}

// The same bits in the signed format: 10-bit two's complement -511 and 511 are at or beyond the
// largest magnitude (2^9 - 1) and unquantise to -0x7FFF and 0x7FFF; x 31 >> 5 on the magnitude
// gives 31743, so index 0 is -65504 (0xFBFF) and index 15 is 65504.
TEST(Bc6h, HandWorkedSignedBlockDecodes) {
  std::uint8_t block[16] = {};
  setModeBits(block, 3);
  for (int c = 0; c < 3; ++c) {
    setBits(block, 5 + 10 * c, 10, 0x201);  // -511
    setBits(block, 35 + 10 * c, 10, 511);
  }
  setBits(block, 65 + 3 + 4 * 14, 4, 15);
  std::uint16_t halves[16][3];
  core::decodeBc6hBlock(block, true, halves);
  EXPECT_EQ(halves[0][0], 0xFBFF);
  EXPECT_EQ(halves[15][0], 0x7BFF);
  EXPECT_EQ(core::bc6hUnquantize(-511, 10, true), -0x7FFF);
  EXPECT_EQ(core::bc6hUnquantize(100, 10, true), ((100 << 15) + 0x4000) >> 9);
}

// Mode 7 (code 7): e0 in 11 bits (10 in order, then bit 10 after r1's delta), deltas of 9 bits
// sign-extended and added to e0, wrapped at 11 bits.
TEST(Bc6h, TransformedEndpointsAreDeltasFromTheFirst) {
  core::Bc6hBlock block;
  block.mode = 11;  // kBc6hModes[11] is code 7
  ASSERT_EQ(core::kBc6hModes[block.mode].code, 7);
  block.fields[0][0] = 1000;
  block.fields[1][0] = 0x1FF;  // -1
  block.fields[0][1] = 2040;
  block.fields[1][1] = 10;  // 2050 wraps at 2048 to 2
  std::uint8_t bytes[16];
  core::packBc6hBlock(block, bytes);
  core::Bc6hBlock read;
  ASSERT_TRUE(core::unpackBc6hBlock(bytes, read));
  int endpoints[4][3];
  core::bc6hEndpoints(read, false, endpoints);
  EXPECT_EQ(endpoints[0][0], 1000);
  EXPECT_EQ(endpoints[1][0], 999);
  EXPECT_EQ(endpoints[1][1], 2);
}

core::Image hdrEnvironment(int width) {
  return core::makeBuiltInEnvironment(core::BuiltInEnvironment::Studio, width / 2);
}

double log2ErrorOf(const core::Image& reference, TextureFormat format,
                   core::CompressionQuality quality, core::Image* decodedOut = nullptr) {
  core::CompressionSettings settings;
  settings.format = format;
  settings.quality = quality;
  core::Result<core::CompressedTexture> texture =
      core::compressMap(reference, core::MapSlot::Height, settings);
  EXPECT_TRUE(texture.ok()) << texture.error();
  core::Image decoded = core::decodeLevel(texture.value()).value();
  const double error = core::measureHdrError(reference, decoded).meanLog2Error;
  if (decodedOut)
    *decodedOut = std::move(decoded);
  return error;
}

// The studio environment spans about 12 stops (dark walls to soft boxes). BC6H keeps it within
// a hundredth of a stop on average: measured 0.0014 at normal, bounded at 0.01.
// Effort pays: best is no worse than normal, normal no worse than fast.
TEST(Bc6h, EncoderKeepsHdrContentWithinAHundredthOfAStop) {
  core::Image studio = hdrEnvironment(256);
  core::Image decoded;
  const double fast = log2ErrorOf(studio, TextureFormat::Bc6h, core::CompressionQuality::Fast);
  const double normal =
      log2ErrorOf(studio, TextureFormat::Bc6h, core::CompressionQuality::Normal, &decoded);
  const double best = log2ErrorOf(studio, TextureFormat::Bc6h, core::CompressionQuality::Best);
  EXPECT_LT(normal, 0.01);
  EXPECT_LE(normal, fast * 1.001);
  EXPECT_LE(best, normal * 1.001);
  const core::HdrError hdr = core::measureHdrError(studio, decoded);
  EXPECT_GT(hdr.exposurePsnr, 40.0);
  RecordProperty("normal_log2_error", std::to_string(normal));
}

// A flat block is stored within half-float rounding (the endpoints' quantisation to 16 bits is
// exact for one-subset mode 15).
TEST(Bc6h, FlatBlocksComeBackWithinHalfRounding) {
  for (float value : {0.0f, 1e-3f, 0.5f, 1.0f, 37.25f, 6000.0f}) {
    core::BlockTexels texels;
    for (auto& texel : texels) {
      texel[0] = value;
      texel[1] = value * 0.5f;
      texel[2] = value * 0.25f;
      texel[3] = 1.0f;
    }
    std::uint8_t block[16];
    core::encodeBc6hBlock(false, core::CompressionQuality::Normal, texels, 0xFFFF, block);
    core::BlockTexels decoded;
    core::decodeBcBlock(TextureFormat::Bc6h, block, decoded);
    for (int c = 0; c < 3; ++c) {
      const float expected = texels[5][c];
      EXPECT_NEAR(decoded[5][c], expected, std::max(1e-7f, std::abs(expected) * 2e-3f))
          << value << " channel " << c;
    }
  }
}

// What half floats cannot hold: NaN becomes 0, infinity the largest half, and the unsigned
// format's negatives 0, while the signed one keeps them. The job warns with the counts.
TEST(Bc6h, ValuesHalfFloatsCannotHoldAreClampedWithAWarning) {
  core::Image map(8, 4, 3);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      for (int c = 0; c < 3; ++c)
        map.at(x, y, c) = 2.0f;
    }
  }
  map.at(0, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  map.at(5, 0, 0) = std::numeric_limits<float>::infinity();
  map.at(1, 1, 1) = -3.0f;
  map.setSourceBitsPerChannel(32);
  const core::HalfFloatClamps unsignedClamps = core::countHalfFloatClamps(map, false);
  EXPECT_EQ(unsignedClamps.notANumber, 1u);
  EXPECT_EQ(unsignedClamps.infinite, 1u);
  EXPECT_EQ(unsignedClamps.negative, 1u);
  EXPECT_EQ(core::countHalfFloatClamps(map, true).negative, 0u);

  core::CompressionJob job;
  job.map = std::make_shared<const core::Image>(map);
  job.slot = core::MapSlot::Height;
  job.settings.format = TextureFormat::Bc6h;
  job.settings.quality = core::CompressionQuality::Best;
  core::Result<core::CompressionOutcome> outcome = core::runCompressionJob(job);
  ASSERT_TRUE(outcome.ok()) << outcome.error();
  ASSERT_EQ(outcome->warnings.size(), 1u);
  EXPECT_NE(outcome->warnings[0].find("1 values are not numbers"), std::string::npos)
      << outcome->warnings[0];
  EXPECT_NE(outcome->warnings[0].find("negative"), std::string::npos);
  const core::Image decoded = core::decodeLevel(*outcome->texture).value();
  EXPECT_TRUE(std::isfinite(decoded.at(0, 0, 0)));
  EXPECT_GT(decoded.at(5, 0, 0), 1000.0f);  // infinity became a large finite value
  EXPECT_GE(decoded.at(1, 1, 1), 0.0f);
  ASSERT_TRUE(outcome->report.hdr.has_value());

  job.settings.format = TextureFormat::Bc6hSigned;
  outcome = core::runCompressionJob(job);
  ASSERT_TRUE(outcome.ok()) << outcome.error();
  EXPECT_LT(core::decodeLevel(*outcome->texture).value().at(1, 1, 1), -1.0f);
}

TEST(Bc6h, EightBitMapsAreRefusedUnlessAsked) {
  core::Image map(8, 8, 1);
  map.setSourceBitsPerChannel(8);
  core::CompressionJob job;
  job.map = std::make_shared<const core::Image>(map);
  job.slot = core::MapSlot::Height;
  job.settings.format = TextureFormat::Bc6h;
  core::Result<core::CompressionOutcome> refused = core::runCompressionJob(job);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().find("8-bit"), std::string::npos) << refused.error();
  job.acceptIntegerMaps = true;
  EXPECT_TRUE(core::runCompressionJob(job).ok());
  // Offered to float maps only; never to normal or colour maps.
  const auto offeredEightBit = core::formatsForMap(map, core::MapSlot::Height);
  EXPECT_EQ(std::count(offeredEightBit.begin(), offeredEightBit.end(), TextureFormat::Bc6h), 0);
  core::Image floatMap(8, 8, 1);
  floatMap.setSourceBitsPerChannel(32);
  const auto offered = core::formatsForMap(floatMap, core::MapSlot::Height);
  EXPECT_NE(std::find(offered.begin(), offered.end(), TextureFormat::Bc6h), offered.end());
  EXPECT_FALSE(core::formatSuitsSlot(TextureFormat::Bc6h, core::MapSlot::Normal));
}

// Both containers carry BC6H: DDS with the DX10 header's DXGI 95/96, KTX2 with vkFormat
// 143/144 and a float (signed) sample in its descriptor; reading gives the same blocks back.
TEST(Bc6h, DdsAndKtx2HoldBothForms) {
  core::Image studio = hdrEnvironment(64);
  for (TextureFormat format : {TextureFormat::Bc6h, TextureFormat::Bc6hSigned}) {
    core::CompressionSettings settings;
    settings.format = format;
    settings.mipmaps = true;
    core::Result<core::CompressedTexture> texture =
        core::compressMap(studio, core::MapSlot::Height, settings);
    ASSERT_TRUE(texture.ok()) << texture.error();
    const std::vector<std::uint8_t> ktx2 = core::encodeKtx2(texture.value(), 19);
    std::uint32_t vkFormat = 0;
    std::memcpy(&vkFormat, ktx2.data() + 12, 4);
    EXPECT_EQ(vkFormat, format == TextureFormat::Bc6h ? 143u : 144u);
    core::Result<std::vector<std::uint8_t>> dds = core::encodeDds(texture.value());
    ASSERT_TRUE(dds.ok()) << dds.error();
    std::uint32_t dxgi = 0;
    std::memcpy(&dxgi, dds->data() + 128, 4);  // the DX10 header follows the 128-byte header
    EXPECT_EQ(dxgi, format == TextureFormat::Bc6h ? 95u : 96u);
    for (const core::Result<core::CompressedTexture>& read :
         {core::decodeKtx2(ktx2, "bc6h.ktx2"), core::decodeDds(dds.value(), "bc6h.dds")}) {
      ASSERT_TRUE(read.ok()) << read.error();
      EXPECT_EQ(read->format, format);
      ASSERT_EQ(read->levels.size(), texture->levels.size());
      EXPECT_EQ(read->levels[0].data, texture->levels[0].data);
    }
  }
}

TEST(Bc6h, HdrErrorIsZeroForIdenticalImagesAndCountsStops) {
  core::Image grey(16, 16, 3);
  for (std::size_t i = 0; i < grey.valueCount(); ++i)
    grey.data()[i] = 0.18f;
  const core::HdrError same = core::measureHdrError(grey, grey);
  EXPECT_TRUE(std::isinf(same.exposurePsnr));
  EXPECT_EQ(same.meanLog2Error, 0.0);
  // Mid grey is the key: the stops are -3..+3.
  EXPECT_EQ(same.firstStop, -3);
  EXPECT_EQ(same.lastStop, 3);
  // Twice as bright everywhere is one stop off (e = 2^-14 moves it by under 0.001).
  core::Image doubled = grey;
  for (std::size_t i = 0; i < doubled.valueCount(); ++i)
    doubled.data()[i] *= 2.0f;
  EXPECT_NEAR(core::measureHdrError(grey, doubled).meanLog2Error, 1.0, 1e-3);
}

}  // namespace
}  // namespace relief::test
