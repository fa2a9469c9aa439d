// MaterialRenderer: draws a mesh with a material for a frame (view, debug view, output kind,
// optional A/B split). The viewport, the offscreen renderer (CLI, thumbnails, tests) and the
// error view all call it, so every picture Relief makes comes from this one code path. All
// calls need the same current context.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "core/material/Material.h"
#include "core/mesh/Mesh.h"
#include "renderer/EnvironmentLight.h"
#include "renderer/FrameSettings.h"
#include "renderer/FrameTimes.h"
#include "renderer/GpuMesh.h"
#include "renderer/ShaderProgram.h"
#include "renderer/TextureCache.h"

#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLTexture>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace relief::renderer {

class MaterialRenderer : protected QOpenGLExtraFunctions {
 public:
  MaterialRenderer();
  ~MaterialRenderer();
  MaterialRenderer(const MaterialRenderer&) = delete;
  MaterialRenderer& operator=(const MaterialRenderer&) = delete;

  // Compiles the base shaders and creates GL objects; fails with the mapped shader log.
  core::Status initialize();
  // Frees every GL object; call with the context current (before it is destroyed).
  void releaseResources();

  void setMesh(const core::Mesh& mesh);
  void setMaterial(const core::Material& material);
  const core::Material& material() const { return m_material; }

  // Draws into `framebuffer` (the window's or an FBO) at width x height pixels. A shader
  // variant that does not compile leaves the background and returns the mapped log.
  core::Status render(const FrameSettings& frame, int width, int height, unsigned framebuffer);
  // The same frame drawn at `scale` (0 < scale <= 1) of width x height into a framebuffer of
  // the renderer's own, then stretched over `framebuffer`'s width x height with bilinear
  // filtering: an interactive frame that costs about scale^2 of a full one. Scale 1 is render().
  // Display output only (a stretched data view would mix values that do not mix).
  core::Status renderReduced(const FrameSettings& frame, int width, int height, float scale,
                             unsigned framebuffer);
  // The pixel size renderReduced draws at for a scale (at least 1x1).
  static std::pair<int, int> reducedSize(int width, int height, float scale);
  // Progressive refinement of a reduced frame: renderRows draws the GL rows [firstRow, endRow)
  // (counted from the bottom) of the full frame into the renderer's own full-size framebuffer,
  // leaving its other rows as they were; showRefined stretches the last reduced frame over
  // `framebuffer` and copies the refined rows [refinedFrom, height) over it.
  core::Status renderRows(const FrameSettings& frame, int width, int height, int firstRow,
                          int endRow);
  void showRefined(int width, int height, int refinedFrom, unsigned framebuffer);
  // The step between the height map's stored levels in normalised height (1/255 for an 8-bit
  // file, 1/65535 for 16 bits), 0 for float or unknown: where self-shadow rays start above.
  static float heightQuantum(const core::Image* height);

  // Renders into an offscreen framebuffer and reads it back: RGBA8 sRGB for Display output,
  // RGBA32F for data. Rows top first. A `scale` below 1 draws as renderReduced does; with
  // `refinement` too, that reduced frame is then refined as the viewport does once the input
  // rests (renderRows, showRefined).
  core::Result<core::Image> renderToImage(const FrameSettings& frame, int width, int height,
                                          float scale = 1.0f,
                                          std::optional<FrameRefinement> refinement = {});
  // Times renders of `frame` into a framebuffer of the size, each drawn and finished
  // (glFinish) on the CPU clock, after one untimed frame (compiling, uploading): at least
  // `timing.minFrames` and, up to `timing.maxFrames`, until `timing.minSeconds` have passed.
  // GL timer queries are not used: llvmpipe reports nonsense for them.
  core::Result<FrameTimes> timeFrames(const FrameSettings& frame, int width, int height,
                                      const FrameTiming& timing);

  // Largest width or height renderToImage accepts on this GPU.
  int maxImageSize();
  // How the compressed previews in `material` reach the GPU, one clause per slot ("Normal BC5
  // (ATI2, 3Dc) uploaded natively"); empty when it has none. Needs the context current.
  std::string compressedUploadSummary(const core::Material& material);
  // See TextureCache::setNativeCompressedUploads.
  void setNativeCompressedUploads(bool native) { m_textures.setNativeCompressedUploads(native); }
  // The viewport builds cone maps off the GUI thread (TextureCache::setDeferredConeMaps); until
  // a material's is provided, its frames are drawn with the quadtree, which finds the same exact
  // surface, so a 4096x4096 height map does not hold the window for seconds.
  void setDeferredConeMaps(bool deferred) { m_textures.setDeferredConeMaps(deferred); }
  bool coneMapReady(const core::Material& material) const {
    return material.technique() != core::Technique::Cone || m_textures.coneMapReady(material);
  }
  void provideConeMap(const core::Material& material, const core::ConeMap& cones) {
    m_textures.provideConeMap(material, cones);
  }
  // Why the last frame's environment could not be used ("" when it could): it was lit by the
  // uniform white environment instead. Files are checked before they reach a view (the Light
  // panel, the CLI), so this is for one that went missing since (a preset's).
  const std::string& environmentError() const { return m_environmentError; }
  // The prefiltered environment of the last frame that needed one, for tests and tools.
  EnvironmentLight& environmentLight() { return m_environment; }
  // GL_RENDERER and GL_VERSION, for the status bar and reports.
  std::string rendererDescription();

 private:
  ShaderProgram* programFor(const core::Material& material, const FrameSettings& frame,
                            std::string& error);
  // Prefilters the view's environment when the frame needs it (pbr shading, or a background
  // that shows it) and it changed; see environmentError().
  void prepareEnvironment(const FrameSettings& frame);
  void drawBackground(const RenderView& view, int width, int height);
  void bindEnvironment(QOpenGLShaderProgram& program, const core::Environment& environment);
  // The engine preview's trace for this material, when the frame asks for one.
  static std::optional<core::EngineTraceParams> engineTraceFor(const core::Material& material,
                                                               const FrameSettings& frame);
  // `material`, or `standIn` set to it with the quadtree while its cone map is being built.
  const core::Material& drawable(const core::Material& material, core::Material& standIn) const;
  void createSplitSumTable();  // pbr shading's (A, B) table (core/shading/SplitSumLut.h)
  // `width` x `height`: the viewport in pixels.
  void drawMaterial(ShaderProgram& program, const core::Material& material,
                    const FrameSettings& frame, int width, int height);
  void setUniforms(QOpenGLShaderProgram& program, const core::Material& material,
                   const FrameSettings& frame, int width, int height);

  bool m_initialized = false;
  std::map<std::string, std::unique_ptr<ShaderProgram>> m_materialPrograms;
  std::map<core::Background, ShaderProgram> m_backgroundPrograms;
  EnvironmentLight m_environment;
  std::string m_environmentError;
  GpuMesh m_mesh;
  core::Bounds m_meshBounds;
  float m_meshWorldPerUv = 1.0f;  // core::worldUnitsPerUv, for the displacement technique
  TextureCache m_textures;
  core::Material m_material;
  unsigned m_emptyVao = 0;  // core profile needs a bound VAO even for attribute-less draws
  // renderReduced's target, kept while its size stays the same (interactive frames come in runs).
  std::unique_ptr<QOpenGLFramebufferObject> m_reducedTarget;
  // renderRows' full-size target and the rows render() is limited to meanwhile (none: all).
  std::unique_ptr<QOpenGLFramebufferObject> m_refineTarget;
  std::optional<std::pair<int, int>> m_rowWindow;
  void scissor(int x, int y, int width, int height);
  std::unique_ptr<QOpenGLTexture> m_splitSumTable;
};

}  // namespace relief::renderer
