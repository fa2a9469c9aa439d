// OffscreenRenderer; see OffscreenRenderer.h.
#include "renderer/OffscreenRenderer.h"

#include "renderer/MaterialRenderer.h"
#include "renderer/OpenGLProbe.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>

#include <algorithm>
#include <vector>

namespace relief::renderer {

OffscreenRenderer::OffscreenRenderer() = default;

OffscreenRenderer::~OffscreenRenderer() {
  if (m_renderer && makeCurrent()) {
    m_renderer->releaseResources();
    m_context->doneCurrent();
  }
}

bool OffscreenRenderer::makeCurrent() {
  return m_context->makeCurrent(m_surface.get());
}

core::Result<std::unique_ptr<OffscreenRenderer>> OffscreenRenderer::create() {
  if (core::Result<std::string> probe = probeOpenGL(); !probe) {
    return core::makeError(probe.error());
  }
  std::unique_ptr<OffscreenRenderer> self(new OffscreenRenderer());
  self->m_context = std::make_unique<QOpenGLContext>();
  self->m_context->setFormat(requiredSurfaceFormat());
  if (!self->m_context->create()) {
    return core::makeError("cannot create an OpenGL 4.1 core context for offscreen rendering");
  }
  self->m_surface = std::make_unique<QOffscreenSurface>();
  self->m_surface->setFormat(self->m_context->format());
  self->m_surface->create();
  if (!self->makeCurrent()) {
    return core::makeError("cannot make the offscreen OpenGL context current");
  }
  QOpenGLExtraFunctions* gl = self->m_context->extraFunctions();
  GLint renderbufferMax = 0;
  GLint viewportMax[2] = {0, 0};
  gl->glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbufferMax);
  gl->glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewportMax);
  self->m_maxSize = std::min({renderbufferMax, viewportMax[0], viewportMax[1]});

  self->m_renderer = std::make_unique<MaterialRenderer>();
  if (core::Status status = self->m_renderer->initialize(); !status) {
    self->m_renderer->releaseResources();
    self->m_renderer.reset();
    return core::makeError(status.error());
  }
  return self;
}

void OffscreenRenderer::setMesh(const core::Mesh& mesh) {
  if (makeCurrent())
    m_renderer->setMesh(mesh);
}

void OffscreenRenderer::setMaterial(const core::Material& material) {
  if (makeCurrent())
    m_renderer->setMaterial(material);
}

core::Result<core::Image> OffscreenRenderer::render(const RenderView& view, int width, int height) {
  if (width < 1 || height < 1 || width > m_maxSize || height > m_maxSize) {
    return core::makeError("cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                           ": sizes must be 1 to " + std::to_string(m_maxSize) +
                           " pixels on this GPU");
  }
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");

  QOpenGLFramebufferObjectFormat format;
  format.setAttachment(QOpenGLFramebufferObject::Depth);
  format.setInternalTextureFormat(GL_RGBA8);
  QOpenGLFramebufferObject fbo(width, height, format);
  if (!fbo.isValid()) {
    return core::makeError("cannot create a " + std::to_string(width) + "x" +
                           std::to_string(height) + " framebuffer (out of GPU memory?)");
  }
  m_renderer->render(view, width, height, fbo.handle());

  QOpenGLExtraFunctions* gl = m_context->extraFunctions();
  std::vector<unsigned char> rgba(std::size_t(width) * std::size_t(height) * 4);
  gl->glBindFramebuffer(GL_FRAMEBUFFER, fbo.handle());
  gl->glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl->glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);

  // GL rows start at the bottom; Image rows start at the top.
  core::Image image(width, height, 4, core::ColorSpace::Srgb);
  image.setSourceBitsPerChannel(8);
  for (int y = 0; y < height; ++y) {
    const unsigned char* row = &rgba[std::size_t(height - 1 - y) * std::size_t(width) * 4];
    float* out = image.pixel(0, y);
    for (int i = 0; i < width * 4; ++i)
      out[i] = float(row[i]) / 255.0f;
  }
  return image;
}

}  // namespace relief::renderer
