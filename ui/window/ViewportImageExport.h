// ViewportImageExport: File > Save Viewport Image. Renders exactly what the viewport shows (its
// material, compressed previews included, camera, light and view) offscreen at any size up to
// what the GPU renders, and saves it as PNG, JPEG or TIFF; failures are reported in a dialog
// that names the file.
#pragma once

#include "ui/Forward.h"

#include <QObject>
#include <QString>

class QWidget;

namespace relief::ui::inline window {

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
