// ViewportWidget: the 3D view of the material. Hands its GL context to the renderer (widgets
// never call GL themselves), renders the view document (ui/document/ViewDocument) and turns mouse
// input into its edits (camera, light) and into moves of the A/B divider,
// paints overlays (heat-map legends, the A/B divider, the error view) and redraws only when
// the document, the view or the size changed. While the user drags (a slider, the camera, the
// light), frames are drawn at a reduced resolution that keeps them within a time budget, and the
// full resolution follows once the input rests.
#pragma once

#include "core/compression/Compressor.h"
#include "core/tracing/UvErrorMap.h"
#include "renderer/FrameSettings.h"
#include "renderer/TextureCache.h"
#include "ui/Forward.h"
#include "ui/viewport/AdaptiveResolution.h"
#include "ui/viewport/ViewNavigation.h"

#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>

#include <atomic>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace relief::renderer {
class MaterialRenderer;
}

namespace relief::ui::inline viewport {

class ViewportWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  // Renders `document`'s material as `view` says (camera, light, environment, display, mesh,
  // debug view); mouse input becomes edits of `view`.
  ViewportWidget(MaterialDocument* document, ViewDocument* view, QWidget* parent = nullptr);
  ~ViewportWidget() override;

  // What the frames show of the view document, as the renderer takes it.
  const renderer::RenderView& view() const { return m_frame.view; }

  // A/B comparison: B (right of the divider) is a held copy of the material.
  bool isComparing() const { return m_frame.split.has_value(); }
  void setComparing(bool on);
  void holdCurrentAsComparison();
  const core::Material* comparisonMaterial() const;
  float dividerFraction() const { return m_dividerFraction; }
  void setDividerFraction(float fraction);

  // See MaterialRenderer::setNativeCompressedUploads; applied at the next frame.
  void setNativeCompressedUploads(bool native);
  // How the previews reach the GPU (native or decoded), as of the last frame.
  const QString& compressedUploadSummary() const { return m_uploadSummary; }

  // The frame as the renderer gets it (for offscreen renders of exactly this view).
  renderer::FrameSettings frameSettings() const { return shownFrame().second; }
  // The material drawn (left of the divider when there is one) and the frame, exactly as the
  // viewport draws them, compressed previews included.
  std::pair<core::Material, renderer::FrameSettings> shownFrame() const;
  // The error view's last numbers, when it has finished.
  const std::optional<core::UvErrorMap>& errorMap() const;

  // The resolution of the last frame, as a fraction of the full size (1: full resolution).
  float lastFrameScale() const { return m_lastFrameScale; }
  // What a frame drawn while the user drags may cost (AdaptiveResolution::kDefaultBudgetMs).
  void setInteractiveFrameBudget(double milliseconds) {
    m_resolution.setBudgetMilliseconds(milliseconds);
  }

  static constexpr int kDividerGrabPixels = 6;
  static constexpr int kSamplesDelayMs = 400;
  // A reduced frame is refined to the full one once no change came for this long: the full
  // frame is drawn in bands of rows, each within the interactive frame budget, over the
  // stretched reduced frame, and at most kMaxBands of them.
  static constexpr int kRestMs = 250;
  static constexpr int kMaxBands = 8;

 Q_SIGNALS:
  // A frame was drawn in `milliseconds` at `scale` of the full resolution (a band of a
  // refinement reports the reduced frame's scale until the last band, which reports 1).
  void frameRendered(double milliseconds, double scale);
  // Height samples (texel fetches) per covered pixel, the mean, measured once the view has
  // rested (kSamplesDelayMs after the last frame) on a quarter-size steps view.
  void samplesMeasured(double meanPerPixel);
  void rendererReady(const QString& description);
  void renderError(const QString& message);
  void errorViewProgress(int done, int total);     // total 0: finished or cancelled
  void errorViewFinished(const QString& summary);  // core::describeUvError's
  void compressedUploadChanged(const QString& summary);
  // A cone map is being built off the GUI thread (frames use the quadtree meanwhile), or not.
  void coneMapBuilding(bool building);
  // The environment shown cannot be read (the message names the file) and the uniform white
  // lights the material instead; "" when that is over.
  void environmentProblem(const QString& message);

 protected:
  void initializeGL() override;
  void paintGL() override;
  // A new size makes the reduced frame on screen the wrong shape: the next frame is whole.
  void resizeGL(int, int) override {
    m_reducedShown = false;
    m_refinedFrom = -1;
  }
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void showViewDocument();  // the view document's state into the frame, and a redraw
  void releaseGl();
  void releaseGlBeforeContextLoss();
  void changed();  // view, material or frame changed: redraw and drop a stale error view
  // paintGL's steps: the mesh framed and uploaded, the material set; the frame to draw and the
  // compressed material shown, if any.
  std::pair<renderer::FrameSettings, std::optional<core::Material>> prepareFrame();
  // The next band of rows of a refinement, drawn and shown.
  core::Status drawRefinementBand(const renderer::FrameSettings& frame, int pixelWidth,
                                  int pixelHeight);
  // Bookkeeping after a band or a reduced (or full) frame; the scale the screen now shows.
  float finishRefinementBand();
  float finishReducedFrame(double milliseconds, int pixelWidth, int pixelHeight, float scale,
                           bool drawn);
  // The environment's problem and the compressed upload summary, when they changed.
  void reportRendererState(const std::optional<core::Material>& compressed);
  void startErrorView(int width, int height);
  // Starts building the cone map of a material shown with the cone technique, if it lacks one.
  void ensureConeMap(const core::Material& material);
  void measureSamples(int width, int height);
  void paintOverlays();
  int dividerX() const;

  bool hasDivider() const;

  MaterialDocument* m_document;
  ViewDocument* m_view;
  std::unique_ptr<renderer::MaterialRenderer> m_renderer;
  QString m_uploadSummary;
  QString m_environmentProblem;  // the renderer's environmentError() last reported
  bool m_nativeCompressed = true;
  renderer::FrameSettings m_frame;
  float m_dividerFraction = 0.5f;
  bool m_meshDirty = true;
  bool m_framing = false;  // paintGL is framing the camera: no second redraw for it
  DragMode m_drag = DragMode::None;
  int m_lightEdit = 0;  // the view document's interactive edit of the light drag
  QPoint m_lastPos;

  // The samples-per-pixel measurement, after the view rests.
  QTimer* m_samplesTimer;

  // Reduced frames while the user drags; the full frame once the input rests.
  InteractionMonitor* m_interaction;
  AdaptiveResolution m_resolution;
  QTimer* m_restTimer;
  bool m_rested = true;  // no change since the rest timer last fired: draw at full resolution
  float m_lastFrameScale = 1.0f;
  // Progressive refinement (paintGL): whether the frame on screen is a reduced frame of the
  // current state, and the lowest GL row refined so far (-1: not refining).
  bool m_reducedShown = false;
  int m_refinedFrom = -1;

  // The error view: a CPU trace per frame, in the background.
  ErrorViewTrace* m_errorTrace;
  ConeMapBuilder* m_coneMaps;  // the cone map of the height shown
  bool m_errorStale = true;
};

}  // namespace relief::ui::inline viewport
