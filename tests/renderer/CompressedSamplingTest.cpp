// Our decoders against an independent one: the GPU driver (Mesa's llvmpipe here; PLATFORM.md).
// Blocks are uploaded with glCompressedTexImage2D, read back texel by texel with texelFetch into
// a float framebuffer, and compared with core's decoder within 1/255. Random bytes exercise
// every block mode a format has (BC1's three-colour mode, BC4's six-value mode, ETC2's T, H and
// planar modes, every EAC table); ASTC, where random bytes are mostly illegal blocks, uses
// astcenc's encoding of a real map.
#include "core/compression/AstcCodec.h"
#include "core/compression/Compressor.h"
#include "core/image/ColorSpace.h"
#include "core/image/ImageIO.h"
#include "renderer/CompressedUpload.h"
#include "renderer/OpenGLProbe.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <random>

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
    const int width = texture.levels[std::size_t(level)].width;
    const int height = texture.levels[std::size_t(level)].height;
    QOpenGLFramebufferObjectFormat format;
    format.setInternalTextureFormat(GL_RGBA32F);
    QOpenGLFramebufferObject target(width, height, format);
    EXPECT_TRUE(target.bind());
    QOpenGLExtraFunctions& gl = *m_context.extraFunctions();
    gl.glViewport(0, 0, width, height);
    m_program.bind();
    uploaded->bind(0);
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
      {TextureFormat::Etc2A, 4}, {TextureFormat::EacR11, 1}, {TextureFormat::EacRg11, 2}};
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

TEST_F(CompressedSampling, EncodedTexturesAndMipLevelsAgree) {
  const core::Image colour = core::loadImage(sourcePath("samples/tiles/tiles_color.png")).value();
  core::Image crop(72, 40, colour.channels(), colour.colorSpace());
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 72; ++x)
      std::copy_n(colour.pixel(x + 200, y + 200), colour.channels(), crop.pixel(x, y));
  }
  // Encoded colour in sRGB formats (the sampler converts to linear), with mips: BC1, BC3,
  // ETC1 (as ETC2 RGB), ETC2 RGBA and every ASTC size.
  for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc3, TextureFormat::Etc1,
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
  for (TextureFormat format : {TextureFormat::Astc4x4, TextureFormat::Astc8x8}) {
    core::CompressedTexture texture;
    texture.format = format;
    texture.srgb = false;
    texture.levels.push_back(
        {72, 40, core::encodeAstc(format, core::CompressionQuality::Fast, false, rgba).value()});
    EXPECT_LE(worstDifference(texture, 0, 4), kTolerance) << core::textureFormatInfo(format).name;
  }
}

}  // namespace
}  // namespace relief::test
