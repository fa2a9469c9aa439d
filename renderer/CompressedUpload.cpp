// CompressedUpload; see CompressedUpload.h.
#include "renderer/CompressedUpload.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

namespace relief::renderer {
namespace {

bool hasExtension(const char* name) {
  const QOpenGLContext* context = QOpenGLContext::currentContext();
  return context && context->hasExtension(QByteArray(name));
}

bool hasVersion(int major, int minor) {
  const QOpenGLContext* context = QOpenGLContext::currentContext();
  return context && context->format().version() >= qMakePair(major, minor);
}

}  // namespace

std::string formatRequirement(core::TextureFormat format) {
  switch (core::textureFormatInfo(format).gpuFeature) {
    case core::GpuFeature::S3tc:
      return "GL_EXT_texture_compression_s3tc";
    case core::GpuFeature::Rgtc:
      return "OpenGL 3.0 (RGTC)";
    case core::GpuFeature::Bptc:
      return "OpenGL 4.2 or GL_ARB_texture_compression_bptc (BPTC)";
    case core::GpuFeature::Etc2Eac:
      return "OpenGL 4.3 or GL_ARB_ES3_compatibility (ETC2/EAC)";
    case core::GpuFeature::AstcLdr:
      break;
  }
  return "GL_KHR_texture_compression_astc_ldr";
}

bool gpuSupportsFormat(core::TextureFormat format, bool srgb) {
  switch (core::textureFormatInfo(format).gpuFeature) {
    case core::GpuFeature::S3tc:
      return hasExtension("GL_EXT_texture_compression_s3tc") &&
             (!srgb || hasExtension("GL_EXT_texture_sRGB") ||
              hasExtension("GL_EXT_texture_compression_s3tc_srgb"));
    case core::GpuFeature::Rgtc:
      return hasVersion(3, 0) || hasExtension("GL_ARB_texture_compression_rgtc");
    case core::GpuFeature::Bptc:
      return hasVersion(4, 2) || hasExtension("GL_ARB_texture_compression_bptc");
    case core::GpuFeature::Etc2Eac:
      return hasVersion(4, 3) || hasExtension("GL_ARB_ES3_compatibility");
    case core::GpuFeature::AstcLdr:
      break;
  }
  return hasExtension("GL_KHR_texture_compression_astc_ldr");
}

std::unique_ptr<QOpenGLTexture> createCompressedTexture(const core::CompressedTexture& texture) {
  if (texture.levels.empty() || !gpuSupportsFormat(texture.format, texture.srgb))
    return nullptr;
  const core::TextureFormatInfo& info = core::textureFormatInfo(texture.format);
  const GLenum internalFormat =
      texture.srgb && info.glSrgbFormat != 0 ? info.glSrgbFormat : info.glFormat;
  QOpenGLExtraFunctions& gl = *QOpenGLContext::currentContext()->extraFunctions();
  auto result = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
  result->create();
  // Restore whatever the active unit had bound (the renderer binds maps unit by unit and may
  // create this texture in between), as QOpenGLTexture's own uploads do.
  GLint previous = 0;
  gl.glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
  gl.glBindTexture(GL_TEXTURE_2D, result->textureId());
  while (gl.glGetError() != GL_NO_ERROR) {
  }
  for (std::size_t level = 0; level < texture.levels.size(); ++level) {
    const core::CompressedLevel& data = texture.levels[level];
    gl.glCompressedTexImage2D(GL_TEXTURE_2D, GLint(level), internalFormat, data.width, data.height,
                              0, GLsizei(data.data.size()), data.data.data());
  }
  const int last = int(texture.levels.size()) - 1;
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, last);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                     last > 0 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  // X in alpha (DXT5nm, ASTC normal): the shader reads X, Y from red and green.
  if (info.layout == core::FormatLayout::NormalAg)
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, GL_ALPHA);
  const bool failed = gl.glGetError() != GL_NO_ERROR;
  gl.glBindTexture(GL_TEXTURE_2D, GLuint(previous));
  if (failed)
    return nullptr;
  return result;
}

}  // namespace relief::renderer
