// Our decoders against an independent one: the GPU driver (Mesa's llvmpipe here).
// Blocks are uploaded with glCompressedTexImage2D, read back texel by texel with texelFetch into
// a float framebuffer, and compared with core's decoder within 1/255. Random bytes exercise
// every block mode a format has (BC1's three-colour mode, BC4's six-value mode, ETC2's T, H and
// planar modes, every EAC table, BC7's eight modes and its reserved one); BC7 blocks built field
// by field cover every partition, rotation and index selection; ASTC, where random bytes are
// mostly illegal blocks, uses astcenc's encoding of a real map.
#include "core/compression/AstcCodec.h"
#include "core/compression/Bc6hBlock.h"
#include "core/compression/Bc7Block.h"
#include "core/compression/BlockCodecs.h"
#include "core/compression/Compressor.h"
#include "core/compression/MipChain.h"
#include "core/compression/RoughnessFold.h"
#include "core/image/ColorSpace.h"
#include "core/image/ImageIO.h"
#include "core/shading/EnvironmentMaps.h"
#include "renderer/CompressedUpload.h"
#include "renderer/OpenGLProbe.h"
#include "renderer/TextureCache.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <array>
#include <random>
#include <tuple>

namespace relief::test {
namespace {

using core::TextureFormat;

// One 8-bit step (the bound), plus float rounding in the comparison itself. Decoders may
// differ by a step: BC1's thirds and BC4's sevenths are rounded differently by different GPUs.
constexpr double kTolerance = 1.0 / 255.0 + 1e-6;
// llvmpipe's BC5 sampler interpolates the six-value mode (a0 <= a1) with fixed-point weights and
// lands up to two steps from the exact (4 a0 + a1) / 5 ... formula: endpoints 57 and 254, index
// 5, exact 214.6, llvmpipe 213. BC4 blocks with the same bytes sample exactly, and Pillow and
// OpenImageIO decode our BC5 files within one step (TextureFileTest), so the bound is widened
// for this one format only.
constexpr double kBc5Tolerance = 2.0 / 255.0 + 1e-6;
// Drivers may interpolate sRGB BC1-BC3 palettes in linear light, which moves a mid-palette
// texel by a fraction of a step once encoded again; one and a half steps bound it.
constexpr double kSrgbTolerance = 1.5 / 255.0 + 1e-6;

class CompressedSampling : public ::testing::Test {
 protected:
  void SetUp() override {
    m_context.setFormat(renderer::requiredSurfaceFormat());
    ASSERT_TRUE(m_context.create());
    m_surface.setFormat(m_context.format());
    m_surface.create();
    ASSERT_TRUE(m_context.makeCurrent(&m_surface));
    m_program.addShaderFromSourceCode(QOpenGLShader::Vertex,
                                      "#version 410 core\n"
                                      "void main() {\n"
                                      "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                                      "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
                                      "}\n");
    m_program.addShaderFromSourceCode(
        QOpenGLShader::Fragment,
        "#version 410 core\n"
        "uniform sampler2D uTexture;\n"
        "uniform int uLevel;\n"
        "out vec4 colour;\n"
        "void main() {\n"
        "  colour = texelFetch(uTexture, ivec2(gl_FragCoord.xy), uLevel);\n"
        "}\n");
    ASSERT_TRUE(m_program.link()) << m_program.log().toStdString();
    m_vao.create();
  }
  void TearDown() override {
    m_vao.destroy();
    m_context.doneCurrent();
  }

  // What the GPU samples from `level` of the texture: RGBA floats, row 0 the first block row.
  std::vector<float> sampleOnGpu(const core::CompressedTexture& texture, int level) {
    std::unique_ptr<QOpenGLTexture> uploaded = renderer::createCompressedTexture(texture);
    EXPECT_TRUE(uploaded) << "the driver refused " << core::textureFormatInfo(texture.format).name;
    if (!uploaded)
      return {};
    return fetchLevel(*uploaded, texture.levels[std::size_t(level)].width,
                      texture.levels[std::size_t(level)].height, level);
  }

  // The texels of `level` (width x height) as texelFetch reads them: RGBA floats.
  std::vector<float> fetchLevel(QOpenGLTexture& uploaded, int width, int height, int level) {
    QOpenGLFramebufferObjectFormat format;
    format.setInternalTextureFormat(GL_RGBA32F);
    QOpenGLFramebufferObject target(width, height, format);
    EXPECT_TRUE(target.bind());
    QOpenGLExtraFunctions& gl = *m_context.extraFunctions();
    gl.glViewport(0, 0, width, height);
    m_program.bind();
    uploaded.bind(0);
    m_program.setUniformValue("uTexture", 0);
    m_program.setUniformValue("uLevel", level);
    m_vao.bind();
    gl.glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> pixels(std::size_t(width) * std::size_t(height) * 4);
    gl.glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
    target.release();
    return pixels;
  }

  // The largest difference over `channels`, in stored values: the sampler decodes sRGB textures
  // to linear, so its values are encoded back before comparing.
  double worstDifference(const core::CompressedTexture& texture, int level, int channels) {
    const std::vector<float> gpu = sampleOnGpu(texture, level);
    const core::Image ours = core::decodeLevel(texture, level).value();
    double worst = gpu.empty() ? 1.0 : 0.0;
    for (int y = 0; y < ours.height() && !gpu.empty(); ++y) {
      for (int x = 0; x < ours.width(); ++x) {
        for (int c = 0; c < channels; ++c) {
          const float value = ours.at(x, y, c);
          float theirs = gpu[(std::size_t(y) * std::size_t(ours.width()) + std::size_t(x)) * 4 +
                             std::size_t(c)];
          if (texture.srgb && c < 3)
            theirs = core::linearToSrgb(theirs);
          worst = std::max(worst, double(std::abs(theirs - value)));
        }
      }
    }
    return worst;
  }

  QOpenGLContext m_context;
  QOffscreenSurface m_surface;
  QOpenGLShaderProgram m_program;
  QOpenGLVertexArrayObject m_vao;
};

core::CompressedTexture randomBlocks(TextureFormat format, int width, int height,
                                     std::uint32_t seed) {
  core::CompressedTexture texture;
  texture.format = format;
  std::mt19937 random(seed);
  core::CompressedLevel level{width, height, {}};
  level.data.resize(core::compressedLevelSize(format, width, height));
  for (std::uint8_t& byte : level.data)
    byte = std::uint8_t(random() & 0xFF);
  texture.levels.push_back(std::move(level));
  return texture;
}

TEST_F(CompressedSampling, RandomBlocksDecodeAsTheGpuSamplesThem) {
  // Channels the GPU format returns: RGB DXT1 has no alpha (three-colour black is opaque in
  // GL_COMPRESSED_RGB_S3TC_DXT1), BC4 and R11 only red, BC5 and RG11 red and green.
  const std::pair<TextureFormat, int> cases[] = {
      {TextureFormat::Bc1, 3},   {TextureFormat::Bc2, 4},    {TextureFormat::Bc3, 4},
      {TextureFormat::Bc4, 1},   {TextureFormat::Bc5, 2},    {TextureFormat::Etc2, 3},
      {TextureFormat::Etc2A, 4}, {TextureFormat::EacR11, 1}, {TextureFormat::EacRg11, 2},
      {TextureFormat::Bc7, 4}};
  for (const auto& [format, channels] : cases) {
    ASSERT_TRUE(renderer::gpuSupportsFormat(format, false))
        << core::textureFormatInfo(format).name << " needs " << renderer::formatRequirement(format);
    // 64x64: 256 random blocks; 30x18 checks partial edge blocks too.
    for (auto [width, height] : {std::pair{64, 64}, std::pair{30, 18}}) {
      const core::CompressedTexture texture =
          randomBlocks(format, width, height, 1234u + unsigned(format));
      EXPECT_LE(worstDifference(texture, 0, channels),
                format == TextureFormat::Bc5 ? kBc5Tolerance : kTolerance)
          << core::textureFormatInfo(format).name << " " << width << "x" << height;
    }
  }
}

// Blocks rewritten by rate-distortion optimisation (BlockRdo.h: neighbours' bytes spliced in)
// are blocks of their format like any other: llvmpipe samples them as core decodes them. A
// strong lambda, so that most blocks are rewritten.
TEST_F(CompressedSampling, RdoBlocksDecodeAsTheGpuSamplesThem) {
  core::Result<core::Image> photo =
      core::loadImage(sourcePath("samples/cobblestones/cobblestones_color.png"));
  ASSERT_TRUE(photo.ok()) << photo.error();
  core::Image crop(64, 64, 3);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      for (int c = 0; c < 3; ++c)
        crop.at(x, y, c) = photo->at(x + 200, y + 300, c);
    }
  }
  const std::tuple<TextureFormat, core::MapSlot, int> cases[] = {
      {TextureFormat::Bc1, core::MapSlot::Color, 3},
      {TextureFormat::Bc3, core::MapSlot::Color, 4},
      {TextureFormat::Bc4, core::MapSlot::Height, 1},
      {TextureFormat::Bc5, core::MapSlot::Normal, 2},
      {TextureFormat::Bc7, core::MapSlot::Color, 4}};
  for (const auto& [format, slot, channels] : cases) {
    core::CompressionSettings settings;
    settings.format = format;
    settings.rdoLambda = 64.0f;
    core::Result<core::CompressedTexture> texture = core::compressMap(crop, slot, settings);
    ASSERT_TRUE(texture.ok()) << texture.error();
    texture->srgb = false;  // the same blocks, sampled without the sRGB decode
    EXPECT_LE(worstDifference(texture.value(), 0, channels),
              format == TextureFormat::Bc5 ? kBc5Tolerance : kTolerance)
        << core::textureFormatInfo(format).name;
  }
}

// BC7 decodes integer by integer, so llvmpipe and core must agree exactly (half a step bounds
// the float readback). Each block has random endpoints, p-bits and indices; the blocks cover
// all 16 partitions of mode 0, all 64 of modes 1, 2, 3 and 7, and every rotation (and, in mode
// 4, index selection) of modes 4 and 5, 16 blocks each, and mode 6.
TEST_F(CompressedSampling, EveryBc7ModeAndPartitionDecodesAsTheGpuDecodesIt) {
  ASSERT_TRUE(renderer::gpuSupportsFormat(TextureFormat::Bc7, false))
      << renderer::formatRequirement(TextureFormat::Bc7);
  std::mt19937 random(99);
  const auto field = [&](int bits) { return bits ? int(random() % (1u << bits)) : 0; };
  std::vector<core::Bc7Block> blocks;
  for (int m = 0; m < 8; ++m) {
    const core::Bc7Mode& mode = core::kBc7Modes[m];
    const int variants = m == 4 ? 8 : m == 5 ? 4 : m == 6 ? 1 : 1 << mode.partitionBits;
    const int copies = m >= 4 && m <= 5 ? 16 : m == 6 ? 64 : 1;
    for (int variant = 0; variant < variants; ++variant) {
      for (int copy = 0; copy < copies; ++copy) {
        core::Bc7Block block;
        block.mode = m;
        block.partition = mode.partitionBits ? variant : 0;
        block.rotation = mode.rotationBits ? variant % 4 : 0;
        block.indexSelection = mode.indexSelectionBits ? variant / 4 : 0;
        for (int s = 0; s < mode.subsets; ++s) {
          for (int e = 0; e < 2; ++e) {
            for (int c = 0; c < 4; ++c) {
              block.endpoints[s][e][c] =
                  std::uint8_t(field(c < 3 ? mode.colourBits : mode.alphaBits));
            }
            block.pBits[s][e] = std::uint8_t(field(1));
          }
          if (mode.sharedPBits)
            block.pBits[s][1] = block.pBits[s][0];
        }
        for (int t = 0; t < 16; ++t) {
          bool anchor = false;
          for (int s = 0; s < mode.subsets; ++s)
            anchor = anchor || core::bc7Anchor(mode.subsets, block.partition, s) == t;
          block.indices[t] = std::uint8_t(field(mode.indexBits - (anchor ? 1 : 0)));
          if (mode.secondaryIndexBits)
            block.secondaryIndices[t] =
                std::uint8_t(field(mode.secondaryIndexBits - (t == 0 ? 1 : 0)));
        }
        blocks.push_back(block);
      }
    }
  }
  // 16 + 4 x 64 + 8 x 16 + 4 x 16 + 64 = 528 blocks, 32 to a row; the last row is padded with
  // all-zero blocks, the reserved mode, which decodes as transparent black.
  const int blocksWide = 32, blocksHigh = int((blocks.size() + 31) / 32);
  core::CompressedTexture texture;
  texture.format = TextureFormat::Bc7;
  texture.levels.push_back({4 * blocksWide, 4 * blocksHigh, {}});
  texture.levels[0].data.assign(std::size_t(blocksWide * blocksHigh) * 16, 0);
  for (std::size_t b = 0; b < blocks.size(); ++b)
    core::packBc7Block(blocks[b], texture.levels[0].data.data() + 16 * b);
  EXPECT_LE(worstDifference(texture, 0, 4), 0.5 / 255.0);
}

// BC6H in both forms: random bytes with each of the 14 mode numbers written into the low bits,
// every two-subset mode with each of its 32 partitions (bits 77-81, as the specification places
// them), 16 blocks of each one-subset mode, and the reserved codes 19, 23, 27 and 31. The decode
// is integer arithmetic ending in half-float bits, so llvmpipe and core must agree exactly; the
// bound allows one half-float step (2^-10 relative) for a driver that rounds its last step.
// Our own encoder's blocks (a studio environment, 13 stops) go through the same comparison.
TEST_F(CompressedSampling, EveryBc6hModeAndPartitionDecodesAsTheGpuDecodesIt) {
  std::mt19937 random(61);
  std::vector<std::array<std::uint8_t, 16>> blocks;
  const auto randomBlock = [&](int code) {
    std::array<std::uint8_t, 16> block;
    for (std::uint8_t& byte : block)
      byte = std::uint8_t(random());
    block[0] = std::uint8_t(code < 2 ? (block[0] & ~3) | code : (block[0] & ~31) | code);
    return block;
  };
  for (const core::Bc6hMode& mode : core::kBc6hModes) {
    for (int variant = 0; variant < (mode.subsets == 2 ? 32 : 16); ++variant) {
      std::array<std::uint8_t, 16> block = randomBlock(mode.code);
      if (mode.subsets == 2) {
        for (int bit = 0; bit < 5; ++bit) {
          const int position = 77 + bit;
          block[std::size_t(position >> 3)] =
              std::uint8_t((block[std::size_t(position >> 3)] & ~(1 << (position & 7))) |
                           ((variant >> bit) & 1) << (position & 7));
        }
      }
      blocks.push_back(block);
    }
  }
  for (int code : {19, 23, 27, 31})
    blocks.push_back(randomBlock(code));
  const int blocksWide = 32, blocksHigh = int((blocks.size() + 31) / 32);
  const core::Image studio = core::makeBuiltInEnvironment(core::BuiltInEnvironment::Studio, 32);
  for (TextureFormat format : {TextureFormat::Bc6h, TextureFormat::Bc6hSigned}) {
    ASSERT_TRUE(renderer::gpuSupportsFormat(format, false)) << renderer::formatRequirement(format);
    core::CompressedTexture randomTexture;
    randomTexture.format = format;
    randomTexture.levels.push_back({4 * blocksWide, 4 * blocksHigh, {}});
    randomTexture.levels[0].data.assign(std::size_t(blocksWide * blocksHigh) * 16, 0);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      std::copy(blocks[b].begin(), blocks[b].end(),
                randomTexture.levels[0].data.begin() + std::ptrdiff_t(16 * b));
    }
    core::CompressionSettings settings;
    settings.format = format;
    core::Result<core::CompressedTexture> encoded =
        core::compressMap(studio, core::MapSlot::Height, settings);
    ASSERT_TRUE(encoded.ok()) << encoded.error();
    for (const core::CompressedTexture* texture : {&randomTexture, &encoded.value()}) {
      const std::vector<float> gpu = sampleOnGpu(*texture, 0);
      const core::Image ours = core::decodeLevel(*texture, 0).value();
      ASSERT_EQ(gpu.size(), ours.pixelCount() * 4);
      int mismatches = 0;
      for (std::size_t p = 0; p < ours.pixelCount(); ++p) {
        for (std::size_t c = 0; c < 3; ++c) {
          const float mine = ours.data()[p * 4 + c], theirs = gpu[p * 4 + c];
          if (std::abs(mine - theirs) > std::abs(mine) * 0x1p-10f + 1e-7f && mismatches++ < 5) {
            ADD_FAILURE() << core::textureFormatInfo(format).name << " texel "
                          << p % std::size_t(ours.width()) << "," << p / std::size_t(ours.width())
                          << " channel " << c << ": ours " << mine << ", llvmpipe " << theirs;
          }
        }
      }
      EXPECT_EQ(mismatches, 0) << core::textureFormatInfo(format).name;
    }
  }
}

// Our ETC2 encoder's own blocks in every mode it writes: a tile crop (ETC1 and planar blocks),
// smooth gradients (planar) and, per block, two random hues in a checkerboard (T and H); the
// GPU samples them as our decoder does.
TEST_F(CompressedSampling, EncodedEtc2BlocksOfEveryModeDecodeAsTheGpuDecodesThem) {
  const core::Image colour = core::loadImage(sourcePath("samples/tiles/tiles_color.png")).value();
  core::Image image(96, 32, 3);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  float hues[2][3] = {};
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 96; ++x) {
      if (x % 4 == 0 && y % 4 == 0) {
        for (auto& hue : hues) {
          for (float& value : hue)
            value = unit(random);
        }
      }
      for (int c = 0; c < 3; ++c) {
        const float gradient = 0.2f + 0.6f * float(x - 32) / 32.0f * (c == 1 ? 0.5f : 1.0f) +
                               0.004f * float(y * (c + 1));
        image.at(x, y, c) = x < 32   ? colour.at(x + 300, y + 300, c)
                            : x < 64 ? gradient
                                     : hues[(x + y) % 2][c];
      }
    }
  }
  for (core::CompressionQuality quality :
       {core::CompressionQuality::Normal, core::CompressionQuality::Best}) {
    // The blocks compared as UNORM data, exactly (the colour slot makes them sRGB).
    core::CompressedTexture texture =
        core::compressMap(image, core::MapSlot::Color, {TextureFormat::Etc2, quality}).value();
    texture.srgb = false;
    int modes[5] = {};
    const std::vector<std::uint8_t>& blocks = texture.levels[0].data;
    for (std::size_t b = 0; b + 8 <= blocks.size(); b += 8)
      ++modes[int(core::etc2Mode(blocks.data() + b))];
    EXPECT_GT(modes[int(core::Etc2Mode::T)], 0);
    EXPECT_GT(modes[int(core::Etc2Mode::H)], 0);
    EXPECT_GT(modes[int(core::Etc2Mode::Planar)], 0);
    EXPECT_GT(modes[int(core::Etc2Mode::Individual)] + modes[int(core::Etc2Mode::Differential)], 0);
    EXPECT_LE(worstDifference(texture, 0, 3), kTolerance)
        << "etc2 " << core::compressionQualityName(quality);
  }
}

TEST_F(CompressedSampling, EncodedTexturesAndMipLevelsAgree) {
  const core::Image colour = core::loadImage(sourcePath("samples/tiles/tiles_color.png")).value();
  core::Image crop(72, 40, colour.channels(), colour.colorSpace());
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 72; ++x)
      std::copy_n(colour.pixel(x + 200, y + 200), colour.channels(), crop.pixel(x, y));
  }
  // Encoded colour in sRGB formats (the sampler converts to linear), with mips: BC1, BC3, BC7,
  // ETC1 (as ETC2 RGB), ETC2 RGBA and every ASTC size.
  for (TextureFormat format :
       {TextureFormat::Bc1, TextureFormat::Bc3, TextureFormat::Bc7, TextureFormat::Etc1,
        TextureFormat::Etc2A, TextureFormat::Astc4x4, TextureFormat::Astc5x5,
        TextureFormat::Astc6x6, TextureFormat::Astc8x8}) {
    const core::CompressedTexture texture =
        core::compressMap(crop, core::MapSlot::Color,
                          {format, core::CompressionQuality::Fast, true})
            .value();
    ASSERT_TRUE(texture.srgb);
    // The blocks as UNORM data compare exactly; as sRGB the sampler converts to linear.
    core::CompressedTexture unorm = texture;
    unorm.srgb = false;
    for (int level : {0, 2}) {
      EXPECT_LE(worstDifference(unorm, level, 3), kTolerance)
          << core::textureFormatInfo(format).name << " level " << level;
    }
    EXPECT_LE(worstDifference(texture, 0, 3), kSrgbTolerance)
        << core::textureFormatInfo(format).name << " sRGB";
  }
  // ASTC in its linear (UNORM) profile, RGBA.
  core::Image rgba(72, 40, 4);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 72; ++x) {
      for (int c = 0; c < 3; ++c)
        rgba.at(x, y, c) = crop.at(x, y, c);
      rgba.at(x, y, 3) = float(x) / 71.0f;
    }
  }
  // BC7 RGBA from our encoder at every quality (each searches different modes).
  for (core::CompressionQuality quality :
       {core::CompressionQuality::Fast, core::CompressionQuality::Normal,
        core::CompressionQuality::Best}) {
    core::CompressedTexture texture =
        core::compressMap(rgba, core::MapSlot::Color, {TextureFormat::Bc7, quality, false}).value();
    texture.srgb = false;
    EXPECT_LE(worstDifference(texture, 0, 4), 0.5 / 255.0)
        << "bc7 " << core::compressionQualityName(quality);
  }
  for (TextureFormat format : {TextureFormat::Astc4x4, TextureFormat::Astc8x8}) {
    core::CompressedTexture texture;
    texture.format = format;
    texture.srgb = false;
    texture.levels.push_back(
        {72, 40, core::encodeAstc(format, core::CompressionQuality::Fast, false, rgba).value()});
    EXPECT_LE(worstDifference(texture, 0, 4), kTolerance) << core::textureFormatInfo(format).name;
  }
}

// An uncompressed map's texture holds core's mip chain (core/compression/MipChain.h, tested
// against analytic levels in MipFilterTest), not the driver's glGenerateMipmap: every level of a
// height (float, exact), colour (sRGB 8-bit: rounding plus the sampler's decode, kSrgbTolerance)
// and normal map (16-bit) equals core's level for box and Kaiser, the two chains differ, and a
// chain without mipmaps has level 0 alone.
TEST_F(CompressedSampling, MapTexturesHoldCoresMipChain) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto noise = [&](int channels) {
    core::Image image(37, 20, channels);  // odd sizes: partial texels weigh in the box
    for (std::size_t i = 0; i < image.valueCount(); ++i)
      image.data()[i] = unit(random);
    return image;
  };
  const std::pair<core::MapSlot, int> slots[] = {
      {core::MapSlot::Height, 1}, {core::MapSlot::Color, 4}, {core::MapSlot::Normal, 4}};
  for (const auto& [slot, channels] : slots) {
    const core::Image image = noise(channels);
    const double tolerance = slot == core::MapSlot::Height  ? 1e-6
                             : slot == core::MapSlot::Color ? kSrgbTolerance
                                                            : 0.5 / 65535.0 + 1e-6;
    for (core::MipFilter filter : {core::MipFilter::Box, core::MipFilter::Kaiser}) {
      const std::vector<core::Image> chain = core::buildMipChain(image, slot, filter);
      std::unique_ptr<QOpenGLTexture> texture =
          renderer::createMapTexture(image, slot, {true, filter});
      ASSERT_EQ(texture->mipLevels(), int(chain.size()));
      for (int level = 1; level < int(chain.size()); ++level) {
        const core::Image& ours = chain[std::size_t(level)];
        const std::vector<float> gpu = fetchLevel(*texture, ours.width(), ours.height(), level);
        double worst = 0.0;
        for (int y = 0; y < ours.height(); ++y) {
          for (int x = 0; x < ours.width(); ++x) {
            for (int c = 0; c < (slot == core::MapSlot::Height ? 1 : 3); ++c) {
              float theirs =
                  gpu[(std::size_t(y) * std::size_t(ours.width()) + std::size_t(x)) * 4 + c];
              if (slot == core::MapSlot::Color)
                theirs = core::linearToSrgb(theirs);
              worst = std::max(worst, double(std::abs(theirs - ours.at(x, y, c))));
            }
          }
        }
        EXPECT_LE(worst, tolerance)
            << core::mapSlotName(slot) << " " << core::mipFilterName(filter) << " level " << level;
      }
    }
    const std::vector<core::Image> box = core::buildMipChain(image, slot, core::MipFilter::Box);
    const std::vector<core::Image> kaiser =
        core::buildMipChain(image, slot, core::MipFilter::Kaiser);
    EXPECT_NE(box[2], kaiser[2]) << "the filters give different levels to tell apart";
    EXPECT_EQ(renderer::createMapTexture(image, slot, {false, core::MipFilter::Box})->mipLevels(),
              1);
  }
  // A roughness map's chain with the normals' spread folded in (core/compression/RoughnessFold.h)
  // holds core's folded levels, which are rougher than the plain ones.
  const core::Image roughness = noise(1);
  const core::Image normals = noise(3);
  const std::vector<core::Image> folded =
      core::foldedRoughnessLevels(roughness, normals, core::MipFilter::Box);
  std::unique_ptr<QOpenGLTexture> texture = renderer::createMapTexture(
      roughness, core::MapSlot::Roughness, {true, core::MipFilter::Box, true}, &normals);
  for (int level = 1; level <= int(folded.size()); ++level) {
    const core::Image& ours = folded[std::size_t(level - 1)];
    const std::vector<float> gpu = fetchLevel(*texture, ours.width(), ours.height(), level);
    for (int y = 0; y < ours.height(); ++y) {
      for (int x = 0; x < ours.width(); ++x) {
        EXPECT_NEAR(gpu[(std::size_t(y) * std::size_t(ours.width()) + std::size_t(x)) * 4],
                    ours.at(x, y, 0), 1e-6)
            << "level " << level;
      }
    }
  }
  const std::vector<core::Image> plain =
      core::buildMipChain(roughness, core::MapSlot::Roughness, core::MipFilter::Box);
  EXPECT_GT(folded[0].at(0, 0, 0), plain[1].at(0, 0, 0));
}

}  // namespace
}  // namespace relief::test
