// EngineGridWindow; see EngineGridWindow.h.
#include "ui/window/EngineGridWindow.h"

#include "core/image/ImageIO.h"
#include "renderer/EngineGrid.h"
#include "renderer/ImageConversion.h"
#include "renderer/OffscreenRenderer.h"
#include "ui/document/ViewDocument.h"
#include "ui/tasks/BackgroundTask.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/ViewportImageExport.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QEventLoop>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>

namespace relief::ui::inline window {
namespace {

// Each panel is drawn at the viewport's size (so the map is read at the viewport's mip levels,
// where the error is measured), at most this wide to bound the exact traces' time, and shown
// scaled to fit the screen.
constexpr int kMaxPanelWidth = 720;
constexpr int kShownWidth = 1500;

}  // namespace

EngineGridWindow::EngineGridWindow(ViewDocument* view, ViewportWidget* viewport, QWidget* parent)
    : QDialog(parent),
      m_view(view),
      m_viewport(viewport),
      m_task(new BackgroundTask(this)),
      m_pictureLabel(new QLabel),
      m_summaryLabel(new QLabel),
      m_save(new QPushButton(tr("Save Image…"))) {
  setObjectName(QStringLiteral("engineGrid"));
  setWindowTitle(tr("Engine Grid"));
  m_pictureLabel->setAlignment(Qt::AlignCenter);
  m_pictureLabel->setMinimumSize(600, 120);
  m_summaryLabel->setWordWrap(true);
  m_summaryLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* explanation = new QLabel(
      tr("The viewport's view drawn by Relief's exact trace and by each engine's own relief "
         "tracer, fed the values its export writes (no self-shadowing: no engine material has "
         "it). The UV error is the mean distance, in height-map texels, from the exact "
         "surface point, over pixels where the map is not minified."));
  explanation->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  QPushButton* refresh = buttons->addButton(tr("Refresh"), QDialogButtonBox::ActionRole);
  refresh->setObjectName(QStringLiteral("refreshGrid"));
  refresh->setToolTip(tr("Draw the viewport's current view again."));
  buttons->addButton(m_save, QDialogButtonBox::ActionRole);
  m_save->setEnabled(false);
  connect(refresh, &QPushButton::clicked, this, &EngineGridWindow::refresh);
  connect(m_save, &QPushButton::clicked, this, &EngineGridWindow::saveImage);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(explanation);
  layout->addWidget(m_pictureLabel, 1);
  layout->addWidget(m_summaryLabel);
  layout->addWidget(buttons);
}

EngineGridWindow::~EngineGridWindow() {
  m_task->cancel();
  m_task->waitForFinished();
}

void EngineGridWindow::refresh() {
  m_task->cancel();
  m_save->setEnabled(false);
  const qreal ratio = m_viewport->devicePixelRatioF();
  const int viewportWidth = std::max(int(m_viewport->width() * ratio), 1);
  const int panelWidth = std::min(viewportWidth, kMaxPanelWidth);
  const int panelHeight =
      std::max(int(panelWidth * double(m_viewport->height() * ratio) / double(viewportWidth)), 60);
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<std::vector<renderer::EngineGridPanelRender>> panels =
      [&]() -> core::Result<std::vector<renderer::EngineGridPanelRender>> {
    renderer::FrameSettings frame;
    auto offscreen = offscreenOfViewport(*m_view, *m_viewport, frame);
    if (!offscreen)
      return core::makeError(offscreen.error());
    return offscreen.value()->renderEngineGridPanels(frame, panelWidth, panelHeight);
  }();
  QApplication::restoreOverrideCursor();
  if (!panels) {
    m_summary = tr("Cannot draw the engine grid: %1").arg(QString::fromStdString(panels.error()));
    m_summaryLabel->setText(m_summary);
    Q_EMIT gridReady();
    return;
  }
  m_summaryLabel->setText(tr("Tracing the exact intersections of every panel…"));
  auto shared =
      std::make_shared<std::vector<renderer::EngineGridPanelRender>>(std::move(panels).value());
  m_task->run<renderer::EngineGrid>(
      [shared](const core::WorkControl& control) {
        return renderer::composeEngineGrid(*shared, control.cancel);
      },
      [this](renderer::EngineGrid&& grid) {
        m_picture = std::move(grid.picture);
        // Scaled to fit the screen (adjustSize would stop at two thirds of it).
        const QImage shown = renderer::toDisplayImage(m_picture);
        const int fit = std::min(kShownWidth, screen()->availableGeometry().width() - 40);
        m_pictureLabel->setPixmap(QPixmap::fromImage(
            shown.width() > fit ? shown.scaledToWidth(fit, Qt::SmoothTransformation) : shown));
        QStringList lines;
        for (const renderer::EngineGridPanel& panel : grid.panels) {
          lines << QStringLiteral("%1: %2").arg(
              QString::fromStdString(panel.label),
              QString::fromStdString(renderer::engineGridErrorCaption(panel)));
        }
        m_summary = lines.join(QLatin1Char('\n'));
        m_summaryLabel->setText(m_summary);
        resize(sizeHint());
        const QRect available = screen()->availableGeometry();
        if (!available.contains(frameGeometry()))
          move(available.center() - rect().center());
        m_save->setEnabled(true);
        Q_EMIT gridReady();
      });
}

void EngineGridWindow::waitForGrid() {
  if (!m_task->isRunning())
    return;
  QEventLoop loop;
  connect(this, &EngineGridWindow::gridReady, &loop, &QEventLoop::quit);
  connect(m_task, &BackgroundTask::cancelled, &loop, &QEventLoop::quit);
  loop.exec();
}

void EngineGridWindow::saveImage() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save Engine Grid"), QStringLiteral("engine-grid.png"), tr("PNG image (*.png)"));
  if (path.isEmpty())
    return;
  if (core::Status saved =
          core::saveImage(m_picture, path.toStdString(), core::SampleFormat::UInt8);
      !saved) {
    QMessageBox::critical(this, tr("Cannot save the engine grid"),
                          tr("%1: %2").arg(path, QString::fromStdString(saved.error())));
  }
}

}  // namespace relief::ui::inline window
