// ViewportImageExport; see ViewportImageExport.h.
#include "ui/window/ViewportImageExport.h"

#include "core/image/ImageIO.h"
#include "renderer/OffscreenRenderer.h"
#include "ui/document/ViewDocument.h"
#include "ui/settings/AppSettings.h"
#include "ui/viewport/ViewportWidget.h"

#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QSpinBox>

namespace relief::ui::inline window {

ViewportImageExport::ViewportImageExport(ViewDocument* view, ViewportWidget* viewport,
                                         QWidget* dialogParent)
    : QObject(dialogParent), m_view(view), m_viewport(viewport), m_parent(dialogParent) {}

core::Result<std::unique_ptr<renderer::OffscreenRenderer>> offscreenOfViewport(
    const ViewDocument& view, const ViewportWidget& viewport, renderer::FrameSettings& frame) {
  auto offscreen = renderer::OffscreenRenderer::create();
  if (!offscreen)
    return core::makeError(offscreen.error());
  offscreen.value()->setMesh(view.mesh());
  auto [material, shown] = viewport.shownFrame();
  offscreen.value()->setMaterial(material);
  frame = std::move(shown);
  return offscreen;
}

bool ViewportImageExport::save(const QString& path, int width, int height) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::Image> image = [&]() -> core::Result<core::Image> {
    renderer::FrameSettings frame;
    auto offscreen = offscreenOfViewport(*m_view, *m_viewport, frame);
    if (!offscreen)
      return core::makeError(offscreen.error());
    if (width > offscreen.value()->maxSize() || height > offscreen.value()->maxSize()) {
      return core::makeError(QStringLiteral("%1x%2 is larger than this GPU renders (%3)")
                                 .arg(width)
                                 .arg(height)
                                 .arg(offscreen.value()->maxSize())
                                 .toStdString());
    }
    return offscreen.value()->render(frame, width, height);
  }();
  core::Status saved =
      image ? core::saveImage(image.value(), path.toStdString(), core::SampleFormat::UInt8)
            : core::Status(core::makeError(image.error()));
  QApplication::restoreOverrideCursor();
  if (!saved) {
    QMessageBox::critical(m_parent, tr("Cannot save the viewport image"),
                          tr("%1: %2").arg(path, QString::fromStdString(saved.error())));
    return false;
  }
  Q_EMIT statusMessage(
      tr("Saved %1 (%2x%3)").arg(QFileInfo(path).fileName()).arg(width).arg(height), 6000);
  return true;
}

void ViewportImageExport::choose(const QString& suggestedName) {
  QDialog sizeDialog(m_parent);
  sizeDialog.setWindowTitle(tr("Save viewport image"));
  auto* widthBox = new QSpinBox;
  auto* heightBox = new QSpinBox;
  for (QSpinBox* box : {widthBox, heightBox}) {
    box->setRange(16, core::kMaxImageDimension);
    box->setSuffix(tr(" px"));
  }
  // Twice the viewport by default: a sharper picture of exactly what is on screen.
  const qreal scale = 2.0 * m_viewport->devicePixelRatioF();
  widthBox->setValue(int(m_viewport->width() * scale));
  heightBox->setValue(int(m_viewport->height() * scale));
  auto* form = new QFormLayout(&sizeDialog);
  form->addRow(tr("Width"), widthBox);
  form->addRow(tr("Height"), heightBox);
  form->addRow(new QLabel(tr("Rendered offscreen with the viewport's camera, light and view.")));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, &sizeDialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &sizeDialog, &QDialog::reject);
  form->addRow(buttons);
  if (sizeDialog.exec() != QDialog::Accepted)
    return;
  const QString suggested = settings::lastFolder(QStringLiteral("image"), false) +
                            QLatin1Char('/') + suggestedName.section(QLatin1Char('.'), 0, 0) +
                            QStringLiteral(".png");
  const QString path = QFileDialog::getSaveFileName(m_parent, tr("Save viewport image"), suggested,
                                                    tr("Images (*.png *.jpg *.tif)"));
  if (path.isEmpty())
    return;
  if (save(path, widthBox->value(), heightBox->value()))
    settings::setLastFolder(QStringLiteral("image"), QFileInfo(path).absolutePath());
}

}  // namespace relief::ui::inline window
