// EnvironmentLight; see EnvironmentLight.h.
#include "renderer/EnvironmentLight.h"

#include "core/base/ParallelFor.h"

#include <glm/gtc/packing.hpp>

#include <QVector2D>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace relief::renderer {
namespace {

// Filtered importance sampling smooths with the source's mips. The count doubles per level from
// 64 at the first (the narrowest lobe, the most texels) up to 1024: rough levels have few
// texels, and more samples there read finer source levels, which keeps a small bright source
// where it is (a mip texel moves it toward its block's centre). Together about 16 million
// samples, the cost of level 1's 131 thousand texels at 128.
int specularSamples(int level) {
  return std::min(32 << level, 1024);
}
// The irradiance integrates every texel of the source's level at most this wide: the cosine
// lobe is 180 degrees wide, and 64 x 32 texels of 2.8 degrees resolve it (2048 per target
// texel, 4 million in all).
constexpr int kIrradianceSourceWidth = 64;
// The largest half-float; brighter texels (a sun in a photographed sky) are clamped to it.
constexpr float kMaxHalf = 65504.0f;

int mipLevelsFor(int width, int height) {
  return 1 + int(std::floor(std::log2(double(std::max(width, height)))));
}

std::unique_ptr<QOpenGLTexture> makeHalfTexture(int width, int height, int levels) {
  auto texture = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
  texture->setFormat(QOpenGLTexture::RGBA16F);
  texture->setSize(width, height);
  texture->setMipLevels(levels);
  texture->allocateStorage(QOpenGLTexture::RGBA, QOpenGLTexture::Float16);
  // Around the vertical axis the map wraps; over the poles it does not.
  texture->setWrapMode(QOpenGLTexture::DirectionS, QOpenGLTexture::Repeat);
  texture->setWrapMode(QOpenGLTexture::DirectionT, QOpenGLTexture::ClampToEdge);
  texture->setMinMagFilters(
      levels > 1 ? QOpenGLTexture::LinearMipMapLinear : QOpenGLTexture::Linear,
      QOpenGLTexture::Linear);
  return texture;
}

}  // namespace

EnvironmentLight::EnvironmentLight() = default;

EnvironmentLight::~EnvironmentLight() = default;

core::Status EnvironmentLight::initialize() {
  initializeOpenGLFunctions();
  if (core::Status status =
          m_specularProgram.build("background.vert", "environment_prefilter.frag", {"SPECULAR"});
      !status) {
    return status;
  }
  if (core::Status status =
          m_irradianceProgram.build("background.vert", "environment_prefilter.frag");
      !status) {
    return status;
  }
  glGenFramebuffers(1, &m_framebuffer);
  glGenVertexArrays(1, &m_emptyVao);
  const int specularHeight = kSpecularWidth / 2;
  m_specular = makeHalfTexture(kSpecularWidth, specularHeight, kSpecularLevels);
  m_irradiance = makeHalfTexture(kIrradianceWidth, kIrradianceWidth / 2, 1);
  return {};
}

void EnvironmentLight::release() {
  m_specularProgram.release();
  m_irradianceProgram.release();
  m_source.reset();
  m_specular.reset();
  m_irradiance.reset();
  m_prepared.reset();
  if (m_framebuffer)
    glDeleteFramebuffers(1, &m_framebuffer);
  if (m_emptyVao)
    glDeleteVertexArrays(1, &m_emptyVao);
  m_framebuffer = 0;
  m_emptyVao = 0;
}

void EnvironmentLight::prepare(const std::shared_ptr<const core::Image>& radiance) {
  if (!radiance || radiance == m_prepared)
    return;
  const auto start = std::chrono::steady_clock::now();
  upload(*radiance);
  for (int level = 0; level < kSpecularLevels; ++level) {
    prefilterInto(*m_specular, level, m_specularProgram, float(level) / float(kSpecularLevels - 1),
                  specularSamples(level));
  }
  prefilterInto(*m_irradiance, 0, m_irradianceProgram, 1.0f, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  m_prefilterMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  m_prepared = radiance;
}

void EnvironmentLight::upload(const core::Image& radiance) {
  const int width = radiance.width();
  const int height = radiance.height();
  const int channels = radiance.channels();
  // Half floats halve the memory of a 4096 x 2048 environment (85 MiB with mips instead of
  // 170) and every GPU filters them.
  std::vector<std::uint16_t> texels(std::size_t(width) * std::size_t(height) * 4);
  core::parallelFor(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const float* source = radiance.pixel(x, y);
      std::uint16_t* target = &texels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
      for (int c = 0; c < 3; ++c) {
        const float value = source[std::min(c, channels - 1)];
        target[c] = glm::packHalf1x16(std::clamp(value, 0.0f, kMaxHalf));
      }
      target[3] = glm::packHalf1x16(1.0f);
    }
  });
  m_source = makeHalfTexture(width, height, mipLevelsFor(width, height));
  // Row 0 is the zenith at t = 0: uploaded as is.
  m_source->setData(0, QOpenGLTexture::RGBA, QOpenGLTexture::Float16, texels.data());
  m_source->generateMipMaps();
}

void EnvironmentLight::prefilterInto(QOpenGLTexture& target, int level, ShaderProgram& shader,
                                     float roughness, int samples) {
  const int width = std::max(target.width() >> level, 1);
  const int height = std::max(target.height() >> level, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.textureId(),
                         level);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  QOpenGLShaderProgram& program = shader.program();
  program.bind();
  m_source->bind(0);
  program.setUniformValue("uSource", 0);
  program.setUniformValue("uSourceSize",
                          QVector2D(float(m_source->width()), float(m_source->height())));
  program.setUniformValue("uTargetSize", QVector2D(float(width), float(height)));
  program.setUniformValue("uSourceMaxLod", float(m_source->mipLevels() - 1));
  program.setUniformValue("uRoughness", roughness);
  program.setUniformValue("uSampleCount", samples);
  int irradianceLod = 0;
  while ((m_source->width() >> irradianceLod) > kIrradianceSourceWidth)
    ++irradianceLod;
  program.setUniformValue("uIrradianceLod", float(irradianceLod));
  glBindVertexArray(m_emptyVao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  program.release();
}

core::Image EnvironmentLight::readSpecularLevel(int level) {
  return readLevel(*m_specular, level);
}

core::Image EnvironmentLight::readIrradiance() {
  return readLevel(*m_irradiance, 0);
}

core::Image EnvironmentLight::readLevel(QOpenGLTexture& texture, int level) {
  const int width = std::max(texture.width() >> level, 1);
  const int height = std::max(texture.height() >> level, 1);
  core::Image image(width, height, 4);
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.textureId(),
                         level);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return image;
}

}  // namespace relief::renderer
