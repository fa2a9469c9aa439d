// ViewportWidget: the 3D view of the material. Hands its GL context to the renderer (widgets
// never call GL themselves), turns mouse and keys into camera, light and divider changes,
// paints overlays (heat-map legends, the A/B divider, the error view) and redraws only when
// the document, the view or the size changed. While the user drags (a slider, the camera, the
// light), frames are drawn at a reduced resolution that keeps them within a time budget, and the
// full resolution follows once the input rests.
#pragma once

#include "core/compression/Compressor.h"
#include "core/mesh/Mesh.h"
#include "core/tracing/UvErrorMap.h"
#include "core/view/DebugView.h"
#include "core/view/ViewState.h"
#include "renderer/FrameSettings.h"
#include "renderer/TextureCache.h"
#include "ui/Forward.h"
#include "ui/viewport/AdaptiveResolution.h"

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
  ViewportWidget(MaterialDocument* document, QWidget* parent = nullptr);
  ~ViewportWidget() override;

  const renderer::RenderView& view() const { return m_frame.view; }
  void setView(const renderer::RenderView& view);
  void setLight(const core::DirectionalLight& light);  // emits lightChanged
  // Whether Ctrl+drag may take the light below the horizon (the Light panel's choice); by
  // default it stops at the horizon.
  void setLightBelowHorizonAllowed(bool allowed) { m_lightBelowHorizon = allowed; }
  // Exposure and tone mapping of the shaded view; emits lightChanged (the Light panel shows it).
  void setDisplayTransform(const core::DisplayTransform& display);
  // pbr shading's image-based light and the background; emits lightChanged. A file source
  // should have been read through core::environmentRadiance first (the Light panel does, off
  // the GUI thread), so the frame finds it ready.
  void setEnvironment(const core::Environment& environment);
  // Places the camera as given, instead of framing the mesh (a preset's saved view).
  void setCamera(const core::OrbitCamera& camera);
  const core::Mesh& mesh() const { return m_mesh; }
  void setMesh(core::Mesh mesh);  // also frames the camera on it (at the next frame)
  // Where the mesh shown comes from: a primitive's name or a mesh file's absolute path.
  const QString& meshSource() const { return m_meshSource; }
  // Shows a primitive by name or imports a mesh file (Assimp). On success returns what to tell
  // the user about an imported file ("N triangles, tangents from the file"), empty for a
  // primitive; the error names the file. Emits meshSourceChanged.
  core::Result<QString> showMesh(const QString& nameOrPath);

  // The mesh, camera, light, environment and display shown, as a preset stores them.
  core::ViewState viewState() const;
  // Shows a preset's view in one call: its mesh when it names one (and it is not already
  // shown), its camera (the mesh framed when it has none) and its light. A mesh that cannot be
  // loaded is the error; the camera and light are applied all the same.
  core::Status showViewState(const core::ViewState& state);

  core::DebugView debugView() const { return m_frame.debugView; }
  void setDebugView(core::DebugView view);

  // A/B comparison: B (right of the divider) is a held copy of the material.
  bool isComparing() const { return m_frame.split.has_value(); }
  void setComparing(bool on);
  void holdCurrentAsComparison();
  const core::Material* comparisonMaterial() const;
  float dividerFraction() const { return m_dividerFraction; }
  void setDividerFraction(float fraction);

  // Compression previews: per slot, a compressed texture of the map the document held when it
  // was made (a slot whose map changed since is shown uncompressed). The view shows the
  // original, the compressed maps, or a wipe with the original left of the divider.
  struct CompressedPreview {
    core::MapSlot slot;
    std::shared_ptr<const core::Image> source;  // the document's map it was made from
    std::shared_ptr<const core::CompressedTexture> texture;
    std::shared_ptr<const core::Image> decoded;
  };
  enum class CompressedView { Original, Compressed, Wipe };
  void setCompressedPreviews(std::vector<CompressedPreview> previews);
  void setCompressedView(CompressedView view);
  // See MaterialRenderer::setNativeCompressedUploads; applied at the next frame.
  void setNativeCompressedUploads(bool native);
  CompressedView compressedView() const { return m_compressedView; }
  // The document's material with every current preview substituted.
  core::Material compressedMaterial() const;
  // How the previews reach the GPU (native or decoded), as of the last frame.
  const QString& compressedUploadSummary() const { return m_uploadSummary; }

  // The frame as the renderer gets it (for offscreen renders of exactly this view).
  renderer::FrameSettings frameSettings() const { return shownFrame().second; }
  // The material drawn (left of the divider when there is one) and the frame, exactly as the
  // viewport draws them, compressed previews included.
  std::pair<core::Material, renderer::FrameSettings> shownFrame() const;
  // The error view's last numbers, when it has finished.
  const std::optional<core::UvErrorMap>& errorMap() const { return m_errorMap; }

  // The resolution of the last frame, as a fraction of the full size (1: full resolution).
  float lastFrameScale() const { return m_lastFrameScale; }
  // What a frame drawn while the user drags may cost (AdaptiveResolution::kDefaultBudgetMs).
  void setInteractiveFrameBudget(double milliseconds) {
    m_resolution.setBudgetMilliseconds(milliseconds);
  }

  static constexpr float kOrbitDegreesPerPixel = 0.4f;
  static constexpr int kDividerGrabPixels = 6;
  static constexpr int kSamplesDelayMs = 400;
  // A reduced frame is refined to the full one once no change came for this long: the full
  // frame is drawn in bands of rows, each within the interactive frame budget, over the
  // stretched reduced frame, and at most kMaxBands of them.
  static constexpr int kRestMs = 250;
  static constexpr int kMaxBands = 8;

 public Q_SLOTS:
  void frameMesh();

 Q_SIGNALS:
  // A frame was drawn in `milliseconds` at `scale` of the full resolution (a band of a
  // refinement reports the reduced frame's scale until the last band, which reports 1).
  void frameRendered(double milliseconds, double scale);
  // Height samples (texel fetches) per covered pixel, the mean, measured once the view has
  // rested (kSamplesDelayMs after the last frame) on a quarter-size steps view.
  void samplesMeasured(double meanPerPixel);
  void rendererReady(const QString& description);
  void renderError(const QString& message);
  void lightChanged();
  void errorViewProgress(int done, int total);     // total 0: finished or cancelled
  void errorViewFinished(const QString& summary);  // core::describeUvError's
  void compressedUploadChanged(const QString& summary);
  void meshSourceChanged(const QString& source);
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
  enum class DragMode { None, Orbit, Light, Pan, Zoom, Divider };
  void releaseGl();
  void releaseGlBeforeContextLoss();
  void changed();  // view, material or frame changed: redraw and drop a stale error view
  void startErrorView(int width, int height);
  // Starts building the cone map of a material shown with the cone technique, if it lacks one.
  void ensureConeMap(const core::Material& material);
  void measureSamples(int width, int height);
  void paintOverlays();
  int dividerX() const;

  bool showsCompressed() const;
  bool hasDivider() const;

  MaterialDocument* m_document;
  std::unique_ptr<renderer::MaterialRenderer> m_renderer;
  std::vector<CompressedPreview> m_previews;
  CompressedView m_compressedView = CompressedView::Original;
  QString m_uploadSummary;
  QString m_environmentProblem;  // the renderer's environmentError() last reported
  bool m_nativeCompressed = true;
  bool m_lightBelowHorizon = false;
  renderer::FrameSettings m_frame;
  float m_dividerFraction = 0.5f;
  core::Mesh m_mesh;
  QString m_meshSource = QStringLiteral("plane");
  bool m_meshDirty = true;
  bool m_framePending = true;
  DragMode m_drag = DragMode::None;
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
  BackgroundTask* m_errorTask;  // the error view's exact trace
  BackgroundTask* m_coneTask;   // the cone map of the height shown
  std::optional<renderer::TracedHeightKey> m_coneBuilding;
  bool m_errorStale = true;
  std::optional<core::UvErrorMap> m_errorMap;
  QImage m_errorImage;
};

}  // namespace relief::ui::inline viewport
