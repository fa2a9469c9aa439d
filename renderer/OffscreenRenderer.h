// OffscreenRenderer: renders a material into a core::Image of any size (up to the GPU's limit)
// through MaterialRenderer, the same code the viewport uses. Owns its own context and
// offscreen surface; needs a QGuiApplication on the xcb platform (an X server or Xvfb).
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "core/material/Material.h"
#include "core/mesh/Mesh.h"
#include "renderer/CostTable.h"
#include "renderer/EngineGrid.h"
#include "renderer/ErrorView.h"
#include "renderer/FrameSettings.h"
#include "renderer/FrameTimes.h"
#include "renderer/SampleCount.h"

#include <memory>
#include <optional>
#include <vector>

class QOpenGLContext;
class QOffscreenSurface;

namespace relief::renderer {

class MaterialRenderer;

// An environment as pbr shading reads it (EnvironmentLight), read back for tests and tools.
struct PrefilteredEnvironment {
  std::vector<core::Image> specular;  // the GGX chain, level 0 (roughness 0) first
  core::Image irradiance;             // E / pi
  double milliseconds = 0.0;          // upload, mips and prefiltering, on the CPU clock
};

class OffscreenRenderer {
 public:
  static core::Result<std::unique_ptr<OffscreenRenderer>> create();
  ~OffscreenRenderer();

  // Largest width or height this context can render, from GL_MAX_RENDERBUFFER_SIZE and
  // GL_MAX_VIEWPORT_DIMS.
  int maxSize() const { return m_maxSize; }

  void setMesh(const core::Mesh& mesh);
  void setMaterial(const core::Material& material);
  // Compressed previews uploaded as blocks (default) or decoded by core.
  void setNativeCompressedUploads(bool native);
  // Rows top first: sRGB RGBA8 values for Display output (exactly what the viewport shows for
  // the same frame), RGBA32F for data outputs. A `scale` below 1 draws the frame smaller and
  // stretches it, as the viewport does while the user drags (MaterialRenderer::renderReduced).
  core::Result<core::Image> render(const FrameSettings& frame, int width, int height,
                                   float scale = 1.0f,
                                   std::optional<FrameRefinement> refinement = {});
  // The shaded material (Display output, no debug view).
  core::Result<core::Image> render(const RenderView& view, int width, int height);
  // Timed frames of `frame` (MaterialRenderer::timeFrames).
  core::Result<FrameTimes> timeFrames(const FrameSettings& frame, int width, int height,
                                      const FrameTiming& timing);
  // Height samples per covered pixel of the frame (SampleCount.h).
  core::Result<SampleCount> countHeightSamples(const FrameSettings& frame, int width, int height);
  // Prefilters the environment `source` names (a built-in or a file, through
  // core::environmentRadiance) and reads the result back. Each call prefilters again.
  core::Result<PrefilteredEnvironment> prefilterEnvironment(const std::string& source);
  // The cost table's frames (see CostTable.h).
  core::Result<CostTable> measureCostTableFrames(const FrameSettings& frame, int width, int height,
                                                 const FrameTiming& timing);
  // The engine grid's GL passes (see EngineGrid.h).
  core::Result<std::vector<EngineGridPanelRender>> renderEngineGridPanels(
      const FrameSettings& frame, int panelWidth, int panelHeight);
  // The two float passes of the error view (see ErrorView.h).
  core::Result<ErrorViewInputs> renderErrorViewInputs(const FrameSettings& frame, int width,
                                                      int height);

 private:
  OffscreenRenderer();
  bool makeCurrent();

  std::unique_ptr<QOpenGLContext> m_context;
  std::unique_ptr<QOffscreenSurface> m_surface;
  std::unique_ptr<MaterialRenderer> m_renderer;
  int m_maxSize = 0;
};

}  // namespace relief::renderer
