// ViewportImageExport: File > Save Viewport Image. Renders exactly what the viewport shows (its
// material, compressed previews included, camera, light and view) offscreen at any size up to
// what the GPU renders, and saves it as PNG, JPEG or TIFF; failures are reported in a dialog
// that names the file.
#pragma once

#include "core/base/Result.h"
#include "renderer/OffscreenRenderer.h"
#include "ui/Forward.h"

#include <QObject>
#include <QString>

#include <memory>

class QWidget;

namespace relief::ui::inline window {

// An offscreen renderer holding exactly what `viewport` shows: `view`'s mesh and the drawn
// material (compressed previews included); `frame` receives the viewport's frame. Shared by
// the viewport image, the engine grid and the cost table, which draw the view offscreen.
core::Result<std::unique_ptr<renderer::OffscreenRenderer>> offscreenOfViewport(
    const ViewDocument& view, const ViewportWidget& viewport, renderer::FrameSettings& frame);

class ViewportImageExport : public QObject {
  Q_OBJECT

 public:
  // The mesh is `view`'s; the material, camera and frame as `viewport` draws them.
  ViewportImageExport(ViewDocument* view, ViewportWidget* viewport, QWidget* dialogParent);

  bool save(const QString& path, int width, int height);
  // Asks for the size (twice the viewport by default) and the file, then saves.
  void choose(const QString& suggestedName);

 Q_SIGNALS:
  void statusMessage(const QString& message, int timeoutMs);

 private:
  ViewDocument* m_view;
  ViewportWidget* m_viewport;
  QWidget* m_parent;
};

}  // namespace relief::ui::inline window
