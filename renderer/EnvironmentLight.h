// EnvironmentLight: an environment's radiance on the GPU, prefiltered for pbr shading's
// image-based light (shaders/environment_prefilter.frag): a mip chain of GGX-prefiltered
// radiance, one level per roughness step, and a diffuse irradiance map, both equirectangular.
// Prefiltering runs once per environment (prepare() with another image), never per frame.
// Needs the renderer's context current for every call.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "renderer/ShaderProgram.h"

#include <QOpenGLExtraFunctions>
#include <QOpenGLTexture>

#include <memory>

namespace relief::renderer {

class EnvironmentLight : protected QOpenGLExtraFunctions {
 public:
  // The specular chain: kSpecularWidth x kSpecularWidth/2 at roughness 0, halving per level
  // down to 16 x 8 at roughness 1 (7 levels); the irradiance, a smooth function, 64 x 32.
  static constexpr int kSpecularWidth = 1024;
  static constexpr int kSpecularLevels = 7;
  static constexpr int kIrradianceWidth = 64;

  EnvironmentLight();
  ~EnvironmentLight();
  EnvironmentLight(const EnvironmentLight&) = delete;
  EnvironmentLight& operator=(const EnvironmentLight&) = delete;

  core::Status initialize();  // compiles the prefilter programs
  void release();

  // Uploads and prefilters `radiance` (core/shading/EnvironmentMaps.h's layout) unless it is
  // the image already prepared. Leaves framebuffer 0 (or none) bound: callers bind theirs after.
  void prepare(const std::shared_ptr<const core::Image>& radiance);
  const std::shared_ptr<const core::Image>& prepared() const { return m_prepared; }
  // How long the last prepare() that prefiltered took (upload, mips, prefilter, glFinish).
  double lastPrefilterMilliseconds() const { return m_prefilterMs; }

  QOpenGLTexture& source() { return *m_source; }
  QOpenGLTexture& specular() { return *m_specular; }
  QOpenGLTexture& irradiance() { return *m_irradiance; }

  // A level of the specular chain or the irradiance map read back (RGBA float, row 0 the
  // zenith), for tests and tools.
  core::Image readSpecularLevel(int level);
  core::Image readIrradiance();

 private:
  void upload(const core::Image& radiance);
  void prefilterInto(QOpenGLTexture& target, int level, ShaderProgram& program, float roughness,
                     int samples);
  core::Image readLevel(QOpenGLTexture& texture, int level);

  ShaderProgram m_specularProgram;
  ShaderProgram m_irradianceProgram;
  std::unique_ptr<QOpenGLTexture> m_source;
  std::unique_ptr<QOpenGLTexture> m_specular;
  std::unique_ptr<QOpenGLTexture> m_irradiance;
  std::shared_ptr<const core::Image> m_prepared;
  unsigned m_framebuffer = 0;
  unsigned m_emptyVao = 0;
  double m_prefilterMs = 0.0;
};

}  // namespace relief::renderer
