// ViewportWidget; see ViewportWidget.h.
#include "ui/ViewportWidget.h"

#include "core/MeshPrimitives.h"
#include "renderer/MaterialRenderer.h"
#include "ui/MaterialDocument.h"

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace relief::ui {

ViewportWidget::ViewportWidget(MaterialDocument* document, QWidget* parent)
    : QOpenGLWidget(parent), m_document(document), m_mesh(core::makePlane()) {
  setMinimumSize(320, 240);
  setFocusPolicy(Qt::StrongFocus);
  setToolTip(
      tr("Drag: orbit the camera\n"
         "Ctrl+drag: move the light\n"
         "Middle-drag or Shift+drag: pan\n"
         "Right-drag or wheel: zoom\n"
         "F: frame the mesh"));
  auto materialTouched = [this] {
    m_materialDirty = true;
    update();
  };
  connect(document, &MaterialDocument::parameterChanged, this, materialTouched);
  connect(document, &MaterialDocument::techniqueChanged, this, materialTouched);
  connect(document, &MaterialDocument::mapChanged, this, materialTouched);
  connect(document, &MaterialDocument::materialReset, this, materialTouched);
}

ViewportWidget::~ViewportWidget() {
  // The context is still alive here; free GL objects while it is current.
  if (context()) {
    // Our slot on aboutToBeDestroyed must not run on a half-destroyed widget.
    disconnect(context(), nullptr, this, nullptr);
    makeCurrent();
    releaseGl();
    doneCurrent();
  }
}

void ViewportWidget::setView(const renderer::RenderView& view) {
  m_view = view;
  update();
}

void ViewportWidget::setMesh(core::Mesh mesh) {
  m_mesh = std::move(mesh);
  m_meshDirty = true;
  m_framePending = true;
  update();
}

void ViewportWidget::frameMesh() {
  const float aspect =
      height() > 0 ? float(width()) / float(height()) : core::OrbitCamera::kDefaultAspect;
  m_view.camera.frame(m_mesh.bounds(), aspect);
  update();
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
  m_meshDirty = true;
  m_materialDirty = true;
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
    frameMesh();
    m_framePending = false;
  }
  if (m_meshDirty) {
    m_renderer->setMesh(m_mesh);
    m_meshDirty = false;
  }
  if (m_materialDirty) {
    m_renderer->setMaterial(m_document->material());
    m_materialDirty = false;
  }
  const qreal ratio = devicePixelRatioF();
  m_renderer->render(m_view, int(std::lround(width() * ratio)), int(std::lround(height() * ratio)),
                     defaultFramebufferObject());
  // Waiting for the GPU makes the status-bar number the real frame cost. The viewport only
  // draws on demand, so the stall never costs an animation frame.
  context()->functions()->glFinish();
  Q_EMIT frameRendered(double(timer.nsecsElapsed()) / 1.0e6);
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  m_lastPos = event->position().toPoint();
  const Qt::KeyboardModifiers modifiers = event->modifiers();
  if (event->button() == Qt::LeftButton) {
    if (modifiers & Qt::ControlModifier) {
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
  const QPoint delta = pos - m_lastPos;
  m_lastPos = pos;
  const float dx = float(delta.x());
  const float dy = float(delta.y());
  switch (m_drag) {
    case DragMode::Orbit:
      m_view.camera.orbit(-dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel);
      break;
    case DragMode::Light: {
      core::DirectionalLight& light = m_view.light;
      light.azimuthDeg = std::fmod(light.azimuthDeg - dx * kOrbitDegreesPerPixel + 360.0f, 360.0f);
      light.elevationDeg =
          std::clamp(light.elevationDeg - dy * kOrbitDegreesPerPixel, -89.0f, 89.0f);
      Q_EMIT lightChanged();
      break;
    }
    case DragMode::Pan:
      m_view.camera.pan(dx / float(std::max(height(), 1)), dy / float(std::max(height(), 1)));
      break;
    case DragMode::Zoom:
      m_view.camera.zoom(std::exp(dy * 0.01f));
      break;
    case DragMode::None:
      return;
  }
  update();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  m_drag = DragMode::None;
  event->accept();
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  // One wheel notch (120 units) zooms by about 12%.
  m_view.camera.zoom(std::exp(-float(event->angleDelta().y()) / 120.0f * 0.12f));
  update();
  event->accept();
}

}  // namespace relief::ui
