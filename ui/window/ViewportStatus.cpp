// ViewportStatus; see ViewportStatus.h.
#include "ui/window/ViewportStatus.h"

#include "ui/document/MaterialDocument.h"
#include "ui/viewport/ViewportWidget.h"

#include <QLabel>
#include <QProgressBar>
#include <QStatusBar>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline window {

ViewportStatus::ViewportStatus(ViewportWidget* viewport, MaterialDocument* document,
                               QStatusBar* bar)
    : QObject(bar),
      m_bar(bar),
      m_progress(new QProgressBar),
      m_compressedLabel(new QLabel),
      m_rendererLabel(new QLabel),
      m_samples(new QLabel),
      m_frameTime(new QLabel) {
  m_progress->setMaximumWidth(220);
  m_progress->setVisible(false);
  bar->addPermanentWidget(m_progress);
  connect(viewport, &ViewportWidget::errorViewProgress, this, [this](int done, int total) {
    m_progress->setVisible(total > 0);
    m_progress->setRange(0, std::max(total, 1));
    m_progress->setValue(done);
  });
  connect(viewport, &ViewportWidget::coneMapBuilding, this, [this](bool building) {
    if (building) {
      m_bar->showMessage(
          tr("Building the cone map; drawn with the quadtree (the same exact surface) meanwhile"));
    } else {
      m_bar->clearMessage();
    }
  });
  connect(viewport, &ViewportWidget::environmentProblem, this, [this](const QString& message) {
    if (message.isEmpty())
      m_bar->clearMessage();
    else
      m_bar->showMessage(tr("%1; lit by the uniform white environment instead").arg(message));
  });
  connect(viewport, &ViewportWidget::errorViewFinished, this, [this](const QString& summary) {
    m_bar->showMessage(tr("UV error against the exact trace: %1").arg(summary), 15000);
  });

  m_frameTime->setToolTip(tr(
      "CPU time of the last frame, including waiting for the GPU. While you drag, frames are "
      "drawn at a reduced resolution that keeps them fluid; the full one follows when you stop."));
  m_frameTime->setMinimumWidth(110);
  m_frameTime->setObjectName(QStringLiteral("frameTime"));
  m_samples->setObjectName(QStringLiteral("samplesPerPixel"));
  m_samples->setToolTip(
      tr("Height samples (texel fetches) per covered pixel, the mean, measured once the view "
         "rests; relief-cli render --stats measures the same"));
  m_compressedLabel->setToolTip(
      tr("Compressed maps are uploaded as blocks (glCompressedTexImage2D) when the driver has "
         "the format, otherwise decoded by Relief"));
  m_compressedLabel->hide();
  bar->addPermanentWidget(m_compressedLabel);
  connect(viewport, &ViewportWidget::compressedUploadChanged, this, [this](const QString& text) {
    m_compressedLabel->setText(text);
    m_compressedLabel->setVisible(!text.isEmpty());
  });
  bar->addPermanentWidget(m_rendererLabel);
  bar->addPermanentWidget(m_samples);
  bar->addPermanentWidget(m_frameTime);
  connect(viewport, &ViewportWidget::frameRendered, this, &ViewportStatus::showFrameTime);
  connect(viewport, &ViewportWidget::samplesMeasured, this,
          [this](double mean) { m_samples->setText(tr("%1 samples/px").arg(mean, 0, 'f', 1)); });
  // The GPU's name alone ("llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa
  // 22.3.6" took half the bar and cut off every message); the whole in the tooltip.
  connect(viewport, &ViewportWidget::rendererReady, this, [this](const QString& description) {
    m_rendererLabel->setText(description.section(QStringLiteral(" ("), 0, 0).section(',', 0, 0));
    m_rendererLabel->setToolTip(description);
  });
  // Messages about the material that was open do not outlive it.
  connect(document, &MaterialDocument::materialReset, bar, &QStatusBar::clearMessage);
}

void ViewportStatus::showFrameTime(double milliseconds, double scale) {
  if (scale < 1.0) {
    // A reduced frame while the user drags; the full one follows when the input rests.
    m_frameTime->setText(tr("frame %1 ms at %2% resolution")
                             .arg(milliseconds, 0, 'f', 1)
                             .arg(int(std::lround(scale * 100.0))));
  } else {
    m_frameTime->setText(tr("frame %1 ms").arg(milliseconds, 0, 'f', 1));
  }
}

}  // namespace relief::ui::inline window
