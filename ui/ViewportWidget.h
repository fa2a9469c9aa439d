// ViewportWidget: the 3D view of the material. Hands its GL context to the renderer (widgets
// never call GL themselves), turns mouse and keys into camera and light changes, and redraws
// only when the document, the view or the size changed.
#pragma once

#include "core/Mesh.h"
#include "renderer/RenderView.h"

#include <QOpenGLWidget>
#include <QPoint>

#include <memory>

namespace relief::renderer {
class MaterialRenderer;
}

namespace relief::ui {

class MaterialDocument;

class ViewportWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  ViewportWidget(MaterialDocument* document, QWidget* parent = nullptr);
  ~ViewportWidget() override;

  const renderer::RenderView& view() const { return m_view; }
  void setView(const renderer::RenderView& view);
  const core::Mesh& mesh() const { return m_mesh; }
  void setMesh(core::Mesh mesh);  // also frames the camera on it (at the next frame)

  // Degrees per pixel dragged, for orbiting the camera and moving the light.
  static constexpr float kOrbitDegreesPerPixel = 0.4f;

 public Q_SLOTS:
  void frameMesh();

 Q_SIGNALS:
  void frameRendered(double milliseconds);
  void rendererReady(const QString& description);
  void renderError(const QString& message);
  void lightChanged();

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  enum class DragMode { None, Orbit, Light, Pan, Zoom };
  void releaseGl();
  void releaseGlBeforeContextLoss();

  MaterialDocument* m_document;
  std::unique_ptr<renderer::MaterialRenderer> m_renderer;
  renderer::RenderView m_view;
  core::Mesh m_mesh;
  bool m_meshDirty = true;
  bool m_framePending = true;
  bool m_materialDirty = true;
  DragMode m_drag = DragMode::None;
  QPoint m_lastPos;
};

}  // namespace relief::ui
