// ViewportWidget; see ViewportWidget.h.
#include "ui/viewport/ViewportWidget.h"

#include "renderer/HeatmapLegend.h"
#include "renderer/ImageConversion.h"
#include "renderer/MaterialRenderer.h"
#include "renderer/SampleCount.h"
#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"
#include "ui/viewport/ConeMapBuilder.h"
#include "ui/viewport/ErrorViewTrace.h"
#include "ui/viewport/InteractionMonitor.h"
#include "ui/viewport/ViewNavigation.h"
#include "ui/viewport/ViewportOverlay.h"

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline viewport {

ViewportWidget::ViewportWidget(MaterialDocument* document, ViewDocument* view, QWidget* parent)
    : QOpenGLWidget(parent),
      m_document(document),
      m_view(view),
      m_samplesTimer(new QTimer(this)),
      m_interaction(new InteractionMonitor(this)),
      m_restTimer(new QTimer(this)),
      m_errorTrace(new ErrorViewTrace(this)),
      m_coneMaps(new ConeMapBuilder(
          [this](const core::Material& material, const core::ConeMap& cones) {
            if (!m_renderer || !isValid())
              return;
            makeCurrent();
            m_renderer->provideConeMap(material, cones);
            doneCurrent();
            update();
          },
          this)) {
  setMinimumSize(320, 240);
  m_samplesTimer->setSingleShot(true);
  m_samplesTimer->setInterval(kSamplesDelayMs);
  // Measured in the widget's context outside paintGL: no frame is redrawn for it.
  connect(m_samplesTimer, &QTimer::timeout, this, [this] {
    if (!m_renderer || !isValid())
      return;
    makeCurrent();
    const qreal ratio = devicePixelRatioF();
    measureSamples(std::max(int(std::lround(width() * ratio)) / 4, 1),
                   std::max(int(std::lround(height() * ratio)) / 4, 1));
    doneCurrent();
  });
  m_restTimer->setSingleShot(true);
  m_restTimer->setInterval(kRestMs);
  connect(m_restTimer, &QTimer::timeout, this, [this] {
    m_rested = true;
    update();
  });
  setFocusPolicy(Qt::StrongFocus);
  setToolTip(
      tr("Drag: orbit the camera\n"
         "Ctrl+drag: move the light\n"
         "Middle-drag or Shift+drag: pan\n"
         "Right-drag or wheel: zoom\n"
         "Drag the divider: move the A/B split\n"
         "F: frame the mesh"));
  auto materialTouched = [this] { changed(); };
  connect(document, &MaterialDocument::parameterChanged, this, materialTouched);
  connect(document, &MaterialDocument::techniqueChanged, this, materialTouched);
  connect(document, &MaterialDocument::mapChanged, this, materialTouched);
  connect(document, &MaterialDocument::materialReset, this, materialTouched);
  connect(document, &MaterialDocument::compressionChanged, this, materialTouched);
  for (auto signal : {&ViewDocument::cameraChanged, &ViewDocument::lightChanged,
                      &ViewDocument::environmentChanged, &ViewDocument::displayChanged,
                      &ViewDocument::debugViewChanged, &ViewDocument::compressedPreviewChanged,
                      &ViewDocument::tilePreviewChanged, &ViewDocument::enginePreviewChanged})
    connect(view, signal, this, &ViewportWidget::showViewDocument);
  connect(view, &ViewDocument::meshChanged, this, [this] {
    m_meshDirty = true;
    showViewDocument();
  });
  connect(view, &ViewDocument::debugViewChanged, m_errorTrace, &ErrorViewTrace::clear);
  showViewDocument();
  connect(m_coneMaps, &ConeMapBuilder::building, this, &ViewportWidget::coneMapBuilding);
  connect(m_errorTrace, &ErrorViewTrace::progress, this, &ViewportWidget::errorViewProgress);
  connect(m_errorTrace, &ErrorViewTrace::finished, this, [this](const QString& summary) {
    Q_EMIT errorViewFinished(summary);
    update();
  });
}

ViewportWidget::~ViewportWidget() {
  // Their work ends after this body, and must not reach this half-destroyed widget.
  disconnect(m_errorTrace, nullptr, this, nullptr);
  delete m_coneMaps;
  if (context()) {
    // Our slot on aboutToBeDestroyed must not run on a half-destroyed widget.
    disconnect(context(), nullptr, this, nullptr);
    makeCurrent();
    releaseGl();
    doneCurrent();
  }
}

void ViewportWidget::changed() {
  m_errorStale = true;
  m_rested = false;
  // The reduced frame on screen shows the state before this change: never refine over it.
  m_reducedShown = false;
  m_refinedFrom = -1;
  if (m_restTimer->isActive())
    m_restTimer->start();  // kRestMs after the last change
  update();
}

void ViewportWidget::showViewDocument() {
  m_frame.view.camera = m_view->camera();
  m_frame.view.light = m_view->light();
  m_frame.view.environment = m_view->environment();
  m_frame.view.display = m_view->display();
  m_frame.debugView = m_view->debugView();
  m_frame.tiles = {m_view->tileRepeats(), m_view->tileSeams(), m_view->hexTiling(),
                   m_view->viewDistance()};
  m_frame.engine = m_view->enginePreview();
  if (!m_framing)
    changed();
}

void ViewportWidget::setComparing(bool on) {
  if (on == isComparing())
    return;
  if (on) {
    m_frame.split = renderer::SplitComparison{m_document->material(), m_dividerFraction};
  } else {
    m_frame.split.reset();
  }
  changed();
}

void ViewportWidget::holdCurrentAsComparison() {
  m_frame.split = renderer::SplitComparison{m_document->material(), m_dividerFraction};
  changed();
}

const core::Material* ViewportWidget::comparisonMaterial() const {
  return m_frame.split ? &m_frame.split->material : nullptr;
}

void ViewportWidget::setNativeCompressedUploads(bool native) {
  m_nativeCompressed = native;
  changed();
}

std::pair<core::Material, renderer::FrameSettings> ViewportWidget::shownFrame() const {
  renderer::FrameSettings frame = m_frame;
  // The chains the maps ship with, original and compressed alike (a preview carries its own).
  for (core::MapSlot slot : core::kAllMapSlots)
    frame.mipChains[std::size_t(slot)] = core::shippedMipChain(m_document->compression(slot));
  if (!m_view->showsCompressed())
    return {m_document->material(), frame};
  // The compressed view replaces a held A/B comparison while it is on.
  if (m_view->compressedView() == ViewDocument::CompressedView::Wipe) {
    frame.split = renderer::SplitComparison{m_view->withCompressedPreviews(m_document->material()),
                                            m_dividerFraction};
    return {m_document->material(), frame};
  }
  frame.split.reset();
  return {m_view->withCompressedPreviews(m_document->material()), frame};
}

bool ViewportWidget::hasDivider() const {
  return m_view->showsCompressed() ? m_view->compressedView() == ViewDocument::CompressedView::Wipe
                                   : m_frame.split.has_value();
}

void ViewportWidget::setDividerFraction(float fraction) {
  m_dividerFraction = std::clamp(fraction, 0.0f, 1.0f);
  if (m_frame.split)
    m_frame.split->dividerFraction = m_dividerFraction;
  update();
}

int ViewportWidget::dividerX() const {
  return int(std::lround(m_dividerFraction * width()));
}

void ViewportWidget::releaseGlBeforeContextLoss() {
  makeCurrent();
  releaseGl();
  doneCurrent();
}

void ViewportWidget::releaseGl() {
  if (m_renderer) {
    m_renderer->releaseResources();
    m_renderer.reset();
  }
}

void ViewportWidget::ensureConeMap(const core::Material& material) {
  if (!m_renderer->coneMapReady(material))
    m_coneMaps->build(material);
}

void ViewportWidget::initializeGL() {
  // The widget's context can be recreated (re-parenting into a floating dock); release the old
  // objects while that context is still current.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
          &ViewportWidget::releaseGlBeforeContextLoss, Qt::UniqueConnection);
  m_renderer = std::make_unique<renderer::MaterialRenderer>();
  if (core::Status status = m_renderer->initialize(); !status) {
    m_renderer->releaseResources();
    m_renderer.reset();
    Q_EMIT renderError(QString::fromStdString(status.error()));
    return;
  }
  m_renderer->setDeferredConeMaps(true);
  m_coneMaps->forget();
  m_meshDirty = true;
  Q_EMIT rendererReady(QString::fromStdString(m_renderer->rendererDescription()));
}

void ViewportWidget::paintGL() {
  if (!m_renderer) {
    QOpenGLFunctions* gl = context()->functions();
    gl->glClearColor(0.3f, 0.0f, 0.0f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  QElapsedTimer timer;
  timer.start();
  auto [frame, compressed] = prepareFrame();
  const qreal ratio = devicePixelRatioF();
  const int pixelWidth = int(std::lround(width() * ratio));
  const int pixelHeight = int(std::lround(height() * ratio));
  if (m_frame.debugView == core::DebugView::Error && m_errorStale)
    startErrorView(pixelWidth, pixelHeight);
  if (frame.debugView == core::DebugView::Error)
    frame.debugView = core::DebugView::Shading;
  // While the user drags, a frame that would take longer than the budget is drawn smaller and
  // stretched; a full frame follows kRestMs after the last change.
  const double fullPixels = double(pixelWidth) * double(pixelHeight);
  const float scale = !m_rested && m_interaction->isInteracting()
                          ? m_resolution.nextInteractiveScale(fullPixels)
                          : 1.0f;
  if (scale >= 1.0f)
    m_resolution.resetScale();
  // Once the input rests after reduced frames, the full frame is drawn in bands of rows, top
  // first, each within the frame budget, over the stretched reduced frame: the picture sharpens
  // band by band, and input is served between bands instead of waiting for a whole slow frame.
  const bool refining = scale >= 1.0f && m_reducedShown;
  const core::Status status = refining
                                  ? drawRefinementBand(frame, pixelWidth, pixelHeight)
                                  : m_renderer->renderReduced(frame, pixelWidth, pixelHeight, scale,
                                                              defaultFramebufferObject());
  if (!status) {
    m_reducedShown = false;
    m_refinedFrom = -1;
    Q_EMIT renderError(QString::fromStdString(status.error()));
  }
  reportRendererState(compressed);
  // Waiting for the GPU makes the status-bar number the real frame cost. The viewport only
  // draws on demand, so the stall never costs an animation frame.
  context()->functions()->glFinish();
  const double milliseconds = double(timer.nsecsElapsed()) / 1.0e6;
  const float shownScale =
      refining ? finishRefinementBand()
               : finishReducedFrame(milliseconds, pixelWidth, pixelHeight, scale, status.ok());
  m_lastFrameScale = shownScale;
  m_samplesTimer->start();  // every frame restarts the wait for the view to rest
  // The renderer binds its maps to units 0 to 15 and leaves the last one active. Qt's OpenGL
  // paint engine remembers the unit it last activated (0) instead of asking GL, so it would
  // bind its own textures (an image, a gradient's colour table) to our active unit and sample
  // unit 0, which holds the colour map: the error view showed the bricks' colour map instead
  // of its heat map, and legends drew grey.
  context()->functions()->glActiveTexture(GL_TEXTURE0);
  paintOverlays();
  Q_EMIT frameRendered(milliseconds, double(shownScale));
}

std::pair<renderer::FrameSettings, std::optional<core::Material>> ViewportWidget::prepareFrame() {
  if (m_view->framingPending()) {
    // Framing needs the real aspect ratio, which is only known once the widget has a size.
    m_framing = true;
    m_view->frameMesh(float(width()) / float(std::max(height(), 1)));
    m_framing = false;
  }
  if (m_meshDirty) {
    m_renderer->setMesh(m_view->mesh());
    m_meshDirty = false;
  }
  m_renderer->setNativeCompressedUploads(m_nativeCompressed);
  auto [material, frame] = shownFrame();
  m_renderer->setMaterial(material);
  ensureConeMap(material);
  if (frame.split)
    ensureConeMap(frame.split->material);
  std::optional<core::Material> compressed;
  if (m_view->showsCompressed())
    compressed = frame.split ? frame.split->material : material;
  return {frame, compressed};
}

core::Status ViewportWidget::drawRefinementBand(const renderer::FrameSettings& frame,
                                                int pixelWidth, int pixelHeight) {
  if (m_refinedFrom < 0)
    m_refinedFrom = pixelHeight;  // GL rows count from the bottom: none refined yet
  const int first = std::max(
      m_refinedFrom - m_resolution.rowsWithinBudget(pixelWidth, pixelHeight, kMaxBands), 0);
  core::Status status =
      m_renderer->renderRows(frame, pixelWidth, pixelHeight, first, m_refinedFrom);
  if (status) {
    m_refinedFrom = first;
    m_renderer->showRefined(pixelWidth, pixelHeight, first, defaultFramebufferObject());
  }
  return status;
}

float ViewportWidget::finishRefinementBand() {
  // A reduced frame being refined is reported at its scale until the last band.
  if (m_refinedFrom > 0) {
    update();  // the next band
    return m_lastFrameScale;
  }
  m_reducedShown = false;
  m_refinedFrom = -1;
  return 1.0f;
}

float ViewportWidget::finishReducedFrame(double milliseconds, int pixelWidth, int pixelHeight,
                                         float scale, bool drawn) {
  const auto [drawnWidth, drawnHeight] =
      renderer::MaterialRenderer::reducedSize(pixelWidth, pixelHeight, scale);
  m_resolution.recordFrame(milliseconds, double(drawnWidth) * double(drawnHeight));
  m_reducedShown = drawn && scale < 1.0f;
  m_refinedFrom = -1;
  // The rest is counted from the end of the reduced frame (and again from each later change):
  // a frame slower than kRestMs must not make the next change's frame a full one.
  if (scale < 1.0f)
    m_restTimer->start();
  return scale;
}

void ViewportWidget::reportRendererState(const std::optional<core::Material>& compressed) {
  if (const QString problem = QString::fromStdString(m_renderer->environmentError());
      problem != m_environmentProblem) {
    m_environmentProblem = problem;
    Q_EMIT environmentProblem(problem);
  }
  const QString summary =
      compressed ? QString::fromStdString(m_renderer->compressedUploadSummary(*compressed))
                 : QString();
  if (summary != m_uploadSummary) {
    m_uploadSummary = summary;
    Q_EMIT compressedUploadChanged(summary);
  }
}

void ViewportWidget::measureSamples(int pixelWidth, int pixelHeight) {
  renderer::FrameSettings frame = shownFrame().second;
  frame.split.reset();  // the live material (A)
  core::Result<renderer::SampleCount> count =
      renderer::countHeightSamples(*m_renderer, frame, pixelWidth, pixelHeight);
  // The count drew into its own framebuffer; the widget's is the one Qt composes.
  context()->functions()->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  if (count && count->pixels > 0)
    Q_EMIT samplesMeasured(count->mean);
}

const std::optional<core::UvErrorMap>& ViewportWidget::errorMap() const {
  return m_errorTrace->map();
}

void ViewportWidget::startErrorView(int pixelWidth, int pixelHeight) {
  m_errorStale = false;
  // The exact trace of every pixel takes seconds on the CPU; progress in the status bar.
  if (core::Status started = m_errorTrace->start(*m_renderer, m_frame, pixelWidth, pixelHeight);
      !started)
    Q_EMIT renderError(QString::fromStdString(started.error()));
}

void ViewportWidget::paintOverlays() {
  ViewportOverlay overlay;
  overlay.errorView = m_frame.debugView == core::DebugView::Error;
  overlay.errorImage = &m_errorTrace->image();
  overlay.errorMap = m_errorTrace->map() ? &*m_errorTrace->map() : nullptr;
  const core::Material& material = m_document->material();
  overlay.legend = renderer::legendFor(m_frame.debugView, material, core::kErrorDisplayTexels);
  if (hasDivider()) {
    overlay.dividerX = dividerX();
    if (m_view->showsCompressed()) {
      QStringList formats;
      for (const ViewDocument::CompressedPreview& preview : m_view->compressedPreviews())
        formats << toQString(core::textureFormatInfo(preview.texture->format).name).toUpper();
      overlay.leftLabel = tr("Original");
      overlay.rightLabel = tr("Compressed: %1").arg(formats.join(QStringLiteral(", ")));
    } else {
      const auto label = [](const core::Material& m) {
        return toQString(core::techniqueName(m.technique()));
      };
      overlay.leftLabel = tr("A (live): %1").arg(label(material));
      overlay.rightLabel = tr("B (held): %1").arg(label(m_frame.split->material));
    }
  }
  QStringList captions;
  if (m_frame.engine) {
    captions << tr("%1 preview: the relief as the exported material traces it")
                    .arg(toQString(core::engineInfo(*m_frame.engine).label));
  }
  if (m_frame.tiles.distance > 1) {
    captions << tr("Seen from ×%1 farther: the mip levels shipped").arg(m_frame.tiles.distance);
  }
  overlay.caption = captions.join(QStringLiteral("  ·  "));
  if (overlay.isEmpty())
    return;  // nothing drawn over the frame
  QPainter painter(this);
  paintViewportOverlay(painter, rect(), overlay);
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  m_lastPos = event->position().toPoint();
  const bool onDivider = hasDivider() && std::abs(m_lastPos.x() - dividerX()) <= kDividerGrabPixels;
  m_drag = dragModeFor(event->button(), event->modifiers(), onDivider);
  if (m_drag == DragMode::Light)
    m_lightEdit = m_view->beginInteractiveEdit();  // the drag is one undo step
  event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPoint pos = event->position().toPoint();
  if (m_drag == DragMode::None && hasDivider()) {
    const bool nearDivider = std::abs(pos.x() - dividerX()) <= kDividerGrabPixels;
    setCursor(nearDivider ? Qt::SplitHCursor : Qt::ArrowCursor);
  }
  const QPoint delta = pos - m_lastPos;
  m_lastPos = pos;
  if (m_drag == DragMode::Divider) {
    setDividerFraction(float(pos.x()) / float(std::max(width(), 1)));
  } else if (m_drag == DragMode::Light) {
    m_view->setLight(draggedLight(m_view->light(), float(delta.x()), float(delta.y()),
                                  m_view->lightBelowHorizonAllowed()),
                     m_lightEdit);
  } else if (m_drag != DragMode::None) {
    m_view->setCamera(
        draggedCamera(m_view->camera(), m_drag, float(delta.x()), float(delta.y()), height()));
  }
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  m_drag = DragMode::None;
  event->accept();
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  m_view->setCamera(wheeledCamera(m_view->camera(), event->angleDelta().y()));
  event->accept();
}

}  // namespace relief::ui::inline viewport
