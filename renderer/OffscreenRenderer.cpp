// OffscreenRenderer; see OffscreenRenderer.h.
#include "renderer/OffscreenRenderer.h"

#include "core/shading/EnvironmentMaps.h"
#include "renderer/MaterialRenderer.h"
#include "renderer/OpenGLProbe.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>

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
  self->m_renderer = std::make_unique<MaterialRenderer>();
  if (core::Status status = self->m_renderer->initialize(); !status) {
    self->m_renderer->releaseResources();
    self->m_renderer.reset();
    return core::makeError(status.error());
  }
  self->m_maxSize = self->m_renderer->maxImageSize();
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

void OffscreenRenderer::setNativeCompressedUploads(bool native) {
  if (makeCurrent())
    m_renderer->setNativeCompressedUploads(native);
}

core::Result<core::Image> OffscreenRenderer::render(const FrameSettings& frame, int width,
                                                    int height, float scale,
                                                    std::optional<FrameRefinement> refinement) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  return m_renderer->renderToImage(frame, width, height, scale, refinement);
}

core::Result<core::Image> OffscreenRenderer::render(const RenderView& view, int width, int height) {
  FrameSettings frame;
  frame.view = view;
  return render(frame, width, height);
}

core::Result<FrameTimes> OffscreenRenderer::timeFrames(const FrameSettings& frame, int width,
                                                       int height, const FrameTiming& timing) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  return m_renderer->timeFrames(frame, width, height, timing);
}

core::Result<SampleCount> OffscreenRenderer::countHeightSamples(const FrameSettings& frame,
                                                                int width, int height) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  return relief::renderer::countHeightSamples(*m_renderer, frame, width, height);
}

core::Result<PrefilteredEnvironment> OffscreenRenderer::prefilterEnvironment(
    const std::string& source) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  core::Result<std::shared_ptr<const core::Image>> radiance = core::environmentRadiance(source);
  if (!radiance)
    return core::makeError(radiance.error());
  EnvironmentLight& light = m_renderer->environmentLight();
  // A copy, so that prepare() sees a new image and prefilters even when this one was shown.
  light.prepare(std::make_shared<const core::Image>(*radiance.value()));
  PrefilteredEnvironment result;
  result.milliseconds = light.lastPrefilterMilliseconds();
  for (int level = 0; level < EnvironmentLight::kSpecularLevels; ++level)
    result.specular.push_back(light.readSpecularLevel(level));
  result.irradiance = light.readIrradiance();
  return result;
}

core::Result<ErrorViewInputs> OffscreenRenderer::renderErrorViewInputs(const FrameSettings& frame,
                                                                       int width, int height) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  return relief::renderer::renderErrorViewInputs(*m_renderer, frame, width, height);
}

core::Result<CostTable> OffscreenRenderer::measureCostTableFrames(const FrameSettings& frame,
                                                                  int width, int height,
                                                                  const FrameTiming& timing) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  return relief::renderer::measureCostTableFrames(*m_renderer, frame, width, height, timing);
}

core::Result<std::vector<EngineGridPanelRender>> OffscreenRenderer::renderEngineGridPanels(
    const FrameSettings& frame, int panelWidth, int panelHeight) {
  if (!makeCurrent())
    return core::makeError("cannot make the offscreen OpenGL context current");
  return relief::renderer::renderEngineGridPanels(*m_renderer, frame, panelWidth, panelHeight);
}

}  // namespace relief::renderer
