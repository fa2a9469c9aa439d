// ViewportWidget; see ViewportWidget.h.
#include "ui/viewport/ViewportWidget.h"

#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"
#include "renderer/ErrorView.h"
#include "renderer/HeatmapLegend.h"
#include "renderer/ImageConversion.h"
#include "renderer/MaterialRenderer.h"
#include "renderer/SampleCount.h"
#include "ui/document/MaterialDocument.h"
#include "ui/tasks/BackgroundTask.h"
#include "ui/viewport/InteractionMonitor.h"
#include "ui/window/QtText.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline viewport {

ViewportWidget::ViewportWidget(MaterialDocument* document, QWidget* parent)
    : QOpenGLWidget(parent),
      m_document(document),
      m_mesh(core::makePrimitive(core::PrimitiveShape::Plane)),
      m_samplesTimer(new QTimer(this)),
      m_interaction(new InteractionMonitor(this)),
      m_restTimer(new QTimer(this)),
      m_errorTask(new BackgroundTask(this)),
      m_coneTask(new BackgroundTask(this)) {
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
  connect(m_errorTask, &BackgroundTask::progress, this,
          [this](double fraction) { Q_EMIT errorViewProgress(int(fraction * 1000.0), 1000); });
  connect(m_errorTask, &BackgroundTask::cancelled, this,
          [this] { Q_EMIT errorViewProgress(0, 0); });
}

ViewportWidget::~ViewportWidget() {
  m_errorTask->cancel();
  m_errorTask->waitForFinished();
  m_coneTask->cancel();
  m_coneTask->waitForFinished();
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

void ViewportWidget::setView(const renderer::RenderView& view) {
  m_frame.view = view;
  changed();
}

void ViewportWidget::setLight(const core::DirectionalLight& light) {
  m_frame.view.light = light;
  changed();
  Q_EMIT lightChanged();
}

void ViewportWidget::setDisplayTransform(const core::DisplayTransform& display) {
  m_frame.view.display = display;
  changed();
  Q_EMIT lightChanged();
}

void ViewportWidget::setEnvironment(const core::Environment& environment) {
  m_frame.view.environment = environment;
  changed();
  Q_EMIT lightChanged();
}

void ViewportWidget::setCamera(const core::OrbitCamera& camera) {
  m_frame.view.camera = camera;
  m_framePending = false;
  changed();
}

void ViewportWidget::setMesh(core::Mesh mesh) {
  m_mesh = std::move(mesh);
  m_meshDirty = true;
  m_framePending = true;
  changed();
}

core::Result<QString> ViewportWidget::showMesh(const QString& nameOrPath) {
  if (const auto shape = core::findPrimitiveShape(nameOrPath.toStdString())) {
    setMesh(core::makePrimitive(*shape));
    m_meshSource = toQString(core::primitiveShapeName(*shape));
    Q_EMIT meshSourceChanged(m_meshSource);
    return QString();
  }
  core::Result<core::ImportedMesh> imported = core::importMesh(nameOrPath.toStdString());
  if (!imported)
    return core::makeError(imported.error());
  const QString summary =
      tr("%1 triangles, tangents %2")
          .arg(imported->mesh.triangleCount())
          .arg(imported->tangentsFromFile ? tr("from the file") : tr("computed"));
  setMesh(std::move(imported->mesh));
  m_meshSource = QFileInfo(nameOrPath).absoluteFilePath();
  Q_EMIT meshSourceChanged(m_meshSource);
  return summary;
}

core::ViewState ViewportWidget::viewState() const {
  return {m_frame.view.camera, m_frame.view.light, m_meshSource.toStdString(), m_frame.view.display,
          m_frame.view.environment};
}

core::Status ViewportWidget::showViewState(const core::ViewState& state) {
  core::Status meshShown;
  const QString mesh = QString::fromStdString(state.mesh);
  if (!mesh.isEmpty() && mesh != m_meshSource) {
    if (core::Result<QString> shown = showMesh(mesh); !shown)
      meshShown = core::makeError(shown.error());
  }
  if (state.camera)
    setCamera(*state.camera);
  else
    frameMesh();
  if (state.light)
    setLight(*state.light);
  if (state.display)
    setDisplayTransform(*state.display);
  if (state.environment)
    setEnvironment(*state.environment);
  return meshShown;
}

void ViewportWidget::frameMesh() {
  const float aspect =
      height() > 0 ? float(width()) / float(height()) : core::OrbitCamera::kDefaultAspect;
  m_frame.view.camera.frame(m_mesh.bounds(), aspect);
  changed();
}

void ViewportWidget::setDebugView(core::DebugView view) {
  m_frame.debugView = view;
  m_errorMap.reset();
  m_errorImage = {};
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

void ViewportWidget::setCompressedPreviews(std::vector<CompressedPreview> previews) {
  m_previews = std::move(previews);
  changed();
}

void ViewportWidget::setNativeCompressedUploads(bool native) {
  m_nativeCompressed = native;
  changed();
}

void ViewportWidget::setCompressedView(CompressedView view) {
  m_compressedView = view;
  changed();
}

bool ViewportWidget::showsCompressed() const {
  return m_compressedView != CompressedView::Original && !m_previews.empty();
}

std::pair<core::Material, renderer::FrameSettings> ViewportWidget::shownFrame() const {
  renderer::FrameSettings frame = m_frame;
  if (!showsCompressed())
    return {m_document->material(), frame};
  // The compressed view replaces a held A/B comparison while it is on.
  if (m_compressedView == CompressedView::Wipe) {
    frame.split = renderer::SplitComparison{compressedMaterial(), m_dividerFraction};
    return {m_document->material(), frame};
  }
  frame.split.reset();
  return {compressedMaterial(), frame};
}

bool ViewportWidget::hasDivider() const {
  return showsCompressed() ? m_compressedView == CompressedView::Wipe : m_frame.split.has_value();
}

core::Material ViewportWidget::compressedMaterial() const {
  core::Material material = m_document->material();
  for (const CompressedPreview& preview : m_previews) {
    if (material.map(preview.slot).image == preview.source)
      material.setCompressedMap(preview.slot, preview.texture, preview.decoded);
  }
  return material;
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
  if (m_renderer->coneMapReady(material))
    return;
  const renderer::TracedHeightKey key = renderer::tracedHeightKey(material);
  if (m_coneBuilding == key)
    return;
  m_coneBuilding = key;
  Q_EMIT coneMapBuilding(true);
  // The snapshot keeps the height's images alive, so its key still names them when it is done.
  m_coneTask->run<core::ConeMap>(
      [material](const core::WorkControl&) { return renderer::buildTracedConeMap(material); },
      [this, material](core::ConeMap&& cones) {
        m_coneBuilding.reset();
        Q_EMIT coneMapBuilding(false);
        if (!m_renderer || !isValid())
          return;
        makeCurrent();
        m_renderer->provideConeMap(material, cones);
        doneCurrent();
        update();
      });
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
  m_coneBuilding.reset();
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
  if (m_framePending) {
    // Framing needs the real aspect ratio, which is only known once the widget has a size.
    const float aspect = float(width()) / float(std::max(height(), 1));
    m_frame.view.camera.frame(m_mesh.bounds(), aspect);
    m_framePending = false;
  }
  if (m_meshDirty) {
    m_renderer->setMesh(m_mesh);
    m_meshDirty = false;
  }
  m_renderer->setNativeCompressedUploads(m_nativeCompressed);
  auto [material, frame] = shownFrame();
  m_renderer->setMaterial(material);
  ensureConeMap(material);
  if (frame.split)
    ensureConeMap(frame.split->material);
  std::optional<core::Material> compressed;
  if (showsCompressed())
    compressed = frame.split ? frame.split->material : material;
  const qreal ratio = devicePixelRatioF();
  const int pixelWidth = int(std::lround(width() * ratio));
  const int pixelHeight = int(std::lround(height() * ratio));
  if (m_frame.debugView == core::DebugView::Error && m_errorStale) {
    startErrorView(pixelWidth, pixelHeight);
  }
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
  core::Status status;
  if (refining) {
    if (m_refinedFrom < 0)
      m_refinedFrom = pixelHeight;  // GL rows count from the bottom: none refined yet
    const int first = std::max(
        m_refinedFrom - m_resolution.rowsWithinBudget(pixelWidth, pixelHeight, kMaxBands), 0);
    status = m_renderer->renderRows(frame, pixelWidth, pixelHeight, first, m_refinedFrom);
    if (status) {
      m_refinedFrom = first;
      m_renderer->showRefined(pixelWidth, pixelHeight, first, defaultFramebufferObject());
    }
  } else {
    status = m_renderer->renderReduced(frame, pixelWidth, pixelHeight, scale,
                                       defaultFramebufferObject());
  }
  if (!status) {
    m_reducedShown = false;
    m_refinedFrom = -1;
    Q_EMIT renderError(QString::fromStdString(status.error()));
  }
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
  // Waiting for the GPU makes the status-bar number the real frame cost. The viewport only
  // draws on demand, so the stall never costs an animation frame.
  context()->functions()->glFinish();
  const double milliseconds = double(timer.nsecsElapsed()) / 1.0e6;
  // What the screen now shows: a reduced frame, a reduced frame being refined (reported at its
  // scale until the last band), or a full frame.
  float shownScale = scale;
  if (refining) {
    const bool done = m_refinedFrom <= 0;
    shownScale = done ? 1.0f : m_lastFrameScale;
    if (done) {
      m_reducedShown = false;
      m_refinedFrom = -1;
    } else {
      update();  // the next band
    }
  } else {
    const auto [drawnWidth, drawnHeight] =
        renderer::MaterialRenderer::reducedSize(pixelWidth, pixelHeight, scale);
    m_resolution.recordFrame(milliseconds, double(drawnWidth) * double(drawnHeight));
    m_reducedShown = status && scale < 1.0f;
    m_refinedFrom = -1;
  }
  m_lastFrameScale = shownScale;
  // The rest is counted from the end of the reduced frame (and again from each later change):
  // a frame slower than kRestMs must not make the next change's frame a full one.
  if (scale < 1.0f && !refining)
    m_restTimer->start();
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

void ViewportWidget::startErrorView(int pixelWidth, int pixelHeight) {
  m_errorStale = false;
  m_errorTask->cancel();
  m_errorMap.reset();
  m_errorImage = {};
  renderer::FrameSettings frame = m_frame;
  auto inputs = renderer::renderErrorViewInputs(*m_renderer, frame, pixelWidth, pixelHeight);
  if (!inputs) {
    Q_EMIT renderError(QString::fromStdString(inputs.error()));
    return;
  }
  // The exact trace of every pixel takes seconds on the CPU; progress in the status bar.
  m_errorTask->run<core::UvErrorMap>(
      [inputs = std::make_shared<renderer::ErrorViewInputs>(std::move(inputs).value())](
          const core::WorkControl& control) {
        return core::computeUvErrorMap(
            inputs->finalUv, inputs->eyeRays, inputs->field,
            [&control](int done, int total) {
              if (done % 16 == 0)
                control.report(double(done) / double(std::max(total, 1)));
            },
            control.cancel);
      },
      [this](core::UvErrorMap&& map) {
        m_errorMap = std::move(map);
        m_errorImage = renderer::toDisplayImage(
            core::colorizeErrorMap(*m_errorMap, core::kErrorDisplayTexels));
        Q_EMIT errorViewProgress(0, 0);
        Q_EMIT errorViewFinished(QString::fromStdString(core::describeUvError(*m_errorMap)));
        update();
      });
}

void ViewportWidget::paintOverlays() {
  const bool errorView = m_frame.debugView == core::DebugView::Error;
  const core::Material& material = m_document->material();
  const auto legend = renderer::legendFor(m_frame.debugView, material, core::kErrorDisplayTexels);
  if (!hasDivider() && !legend && !errorView)
    return;  // nothing drawn over the frame
  QPainter painter(this);
  if (errorView) {
    if (!m_errorImage.isNull()) {
      painter.drawImage(rect(), m_errorImage);
    } else {
      painter.setPen(Qt::white);
      painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignTop | Qt::AlignLeft,
                       tr("Tracing the exact intersections…"));
    }
    if (m_errorMap) {
      painter.setPen(Qt::white);
      painter.drawText(rect().adjusted(12, 12, -12, -12),
                       Qt::AlignTop | Qt::AlignLeft | Qt::TextWordWrap,
                       tr("UV error against the exact trace: %1")
                           .arg(QString::fromStdString(core::describeUvError(*m_errorMap))));
    }
  }
  if (legend)
    renderer::drawHeatmapLegend(painter, rect(), *legend);
  if (hasDivider()) {
    const int x = dividerX();
    painter.setPen(QPen(QColor(255, 255, 255, 200), 2));
    painter.drawLine(x, 0, x, height());
    QString left, right;
    if (showsCompressed()) {
      QStringList formats;
      for (const CompressedPreview& preview : m_previews) {
        formats << toQString(core::textureFormatInfo(preview.texture->format).name).toUpper();
      }
      left = tr("Original");
      right = tr("Compressed: %1").arg(formats.join(QStringLiteral(", ")));
    } else {
      const auto label = [](const core::Material& m) {
        return toQString(core::techniqueName(m.technique()));
      };
      left = tr("A (live): %1").arg(label(material));
      right = tr("B (held): %1").arg(label(m_frame.split->material));
    }
    painter.setPen(Qt::white);
    painter.drawText(QRect(8, 8, std::max(x - 16, 0), 20), Qt::AlignLeft, left);
    painter.drawText(QRect(x + 8, 8, std::max(width() - x - 16, 0), 20), Qt::AlignRight, right);
  }
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  m_lastPos = event->position().toPoint();
  const Qt::KeyboardModifiers modifiers = event->modifiers();
  if (event->button() == Qt::LeftButton) {
    if (hasDivider() && std::abs(m_lastPos.x() - dividerX()) <= kDividerGrabPixels) {
      m_drag = DragMode::Divider;
    } else if (modifiers & Qt::ControlModifier) {
      m_drag = DragMode::Light;
    } else if (modifiers & Qt::ShiftModifier) {
      m_drag = DragMode::Pan;
    } else {
      m_drag = DragMode::Orbit;
    }
  } else if (event->button() == Qt::MiddleButton) {
    m_drag = DragMode::Pan;
  } else if (event->button() == Qt::RightButton) {
    m_drag = DragMode::Zoom;
  }
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
  const float dx = float(delta.x());
  const float dy = float(delta.y());
  core::OrbitCamera& camera = m_frame.view.camera;
  switch (m_drag) {
    case DragMode::Orbit:
      camera.orbit(-dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel);
      break;
    case DragMode::Light: {
      core::DirectionalLight& light = m_frame.view.light;
      light.azimuthDeg = std::fmod(light.azimuthDeg - dx * kOrbitDegreesPerPixel + 360.0f, 360.0f);
      light.elevationDeg = std::clamp(light.elevationDeg - dy * kOrbitDegreesPerPixel,
                                      m_lightBelowHorizon ? -90.0f : 0.0f, 90.0f);
      Q_EMIT lightChanged();
      break;
    }
    case DragMode::Pan:
      camera.pan(dx / float(std::max(height(), 1)), dy / float(std::max(height(), 1)));
      break;
    case DragMode::Zoom:
      camera.zoom(std::exp(dy * 0.01f));
      break;
    case DragMode::Divider:
      setDividerFraction(float(pos.x()) / float(std::max(width(), 1)));
      return;
    case DragMode::None:
      return;
  }
  changed();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  m_drag = DragMode::None;
  event->accept();
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  // One wheel notch (120 units) zooms by about 12%.
  m_frame.view.camera.zoom(std::exp(-float(event->angleDelta().y()) / 120.0f * 0.12f));
  changed();
  event->accept();
}

}  // namespace relief::ui::inline viewport
