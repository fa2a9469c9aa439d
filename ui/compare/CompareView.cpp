// CompareView; see CompareView.h.
#include "ui/compare/CompareView.h"

#include "core/compression/DifferenceImage.h"
#include "core/compression/Flip.h"
#include "core/image/Heatmap.h"
#include "renderer/ImageConversion.h"
#include "ui/tasks/BackgroundTask.h"

#include <QCoreApplication>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace relief::ui::inline compare {
namespace {

constexpr double kMinZoom = 1.0 / 64.0, kMaxZoom = 64.0;
constexpr int kSideGap = 8;  // texels between the two images side by side
constexpr int kDividerGrab = 6;

QString texelText(const core::Image& image, int x, int y) {
  QStringList values;
  for (int c = 0; c < image.channels(); ++c)
    values << QString::number(std::lround(image.at(x, y, c) * 255.0f));
  return values.join(QLatin1Char(' '));
}

}  // namespace

CompareView::CompareView(QWidget* parent) : QWidget(parent), m_flipTask(new BackgroundTask(this)) {
  setMouseTracking(true);
  setMinimumSize(200, 150);
  setFocusPolicy(Qt::StrongFocus);
  setToolTip(tr("Wheel: zoom about the cursor\nDrag: pan\nDrag the divider: move the wipe"));
}

void CompareView::setImages(std::shared_ptr<const core::Image> original,
                            std::shared_ptr<const core::Image> compressed) {
  m_original = std::move(original);
  m_compressed = std::move(compressed);
  m_flipTask->cancel();
  m_flipError.reset();
  m_flipMap = {};
  m_userMoved = false;
  rebuild();
  fitToView();
  updateHover();
}

void CompareView::setMode(Mode mode) {
  m_mode = mode;
  rebuild();
  if (!m_userMoved)
    fitToView();  // side by side is twice as wide
  updateHover();
}

void CompareView::setGain(double gain) {
  m_gain = std::clamp(gain, 1.0, 100.0);
  rebuild();
}

void CompareView::setThreshold(double threshold) {
  m_threshold = std::clamp(threshold, 0.0, 1.0);
  rebuild();
}

void CompareView::setChannel(std::optional<int> channel) {
  m_channel = channel;
  rebuild();
}

void CompareView::setBlockSize(int width, int height) {
  m_blockWidth = std::max(1, width);
  m_blockHeight = std::max(1, height);
  rebuild();
}

void CompareView::setWipeFraction(double fraction) {
  m_wipe = std::clamp(fraction, 0.0, 1.0);
  update();
}

void CompareView::rebuild() {
  if (!m_original || !m_compressed) {
    m_left = m_right = m_difference = {};
    update();
    return;
  }
  m_left = renderer::toDisplayImage(*m_original, m_channel);
  m_right = renderer::toDisplayImage(*m_compressed, m_channel);
  if (m_mode == Mode::Difference) {
    m_difference = renderer::toDisplayImage(
        core::amplifiedDifference(*m_original, *m_compressed, m_gain, m_channel), std::nullopt);
  } else if (m_mode == Mode::Threshold) {
    m_difference = renderer::toDisplayImage(
        core::thresholdedDifference(*m_original, *m_compressed, m_threshold, m_channel),
        std::nullopt);
  } else if (m_mode == Mode::Blocks) {
    // Each block's RMS error x gain on the heat ramp, drawn over the block's texels.
    const core::Image blocks =
        core::blockError(*m_original, *m_compressed, m_blockWidth, m_blockHeight, m_channel);
    m_worstBlock = 0.0;
    for (std::size_t i = 0; i < blocks.valueCount(); ++i)
      m_worstBlock = std::max(m_worstBlock, double(blocks.data()[i]));
    m_difference = QImage(m_original->width(), m_original->height(), QImage::Format_RGB888);
    for (int y = 0; y < m_difference.height(); ++y) {
      uchar* line = m_difference.scanLine(y);
      for (int x = 0; x < m_difference.width(); ++x) {
        const float error = blocks.at(x / m_blockWidth, y / m_blockHeight, 0);
        const glm::vec3 colour = core::heatmapColor(float(std::min(1.0, error * m_gain)));
        for (int c = 0; c < 3; ++c)
          line[3 * x + c] = uchar(std::lround(std::clamp(colour[c], 0.0f, 1.0f) * 255.0f));
      }
    }
  } else if (m_mode == Mode::Flip && !m_flipError) {
    m_flipMap = {};
    if (!m_flipTask->isRunning()) {
      m_flipTask->run<core::FlipResult>(
          [original = m_original, compressed = m_compressed](const core::WorkControl&) {
            return core::measureFlip(*original, *compressed);
          },
          [this](core::FlipResult&& flip) {
            m_flipMean = flip.mean;
            m_flipError = std::move(flip.errorMap);
            rebuild();
          });
    }
  } else if (m_mode == Mode::Flip) {
    // The gain spreads small errors over the ramp, as it amplifies the plain difference.
    m_flipMap = QImage(m_flipError->width(), m_flipError->height(), QImage::Format_RGB888);
    for (int y = 0; y < m_flipMap.height(); ++y) {
      uchar* line = m_flipMap.scanLine(y);
      for (int x = 0; x < m_flipMap.width(); ++x) {
        const glm::vec3 colour =
            core::heatmapColor(float(std::min(1.0, m_flipError->at(x, y, 0) * m_gain)));
        for (int c = 0; c < 3; ++c)
          line[3 * x + c] = uchar(std::lround(std::clamp(colour[c], 0.0f, 1.0f) * 255.0f));
      }
    }
  }
  update();
}

void CompareView::waitForFlip() {
  m_flipTask->waitForFinished();
  while (m_flipTask->isRunning())
    QCoreApplication::processEvents();
}

QPointF CompareView::toWidget(QPointF texel) const {
  return m_offset + texel * m_zoom;
}

QPointF CompareView::toTexel(QPointF widget) const {
  return (widget - m_offset) / m_zoom;
}

void CompareView::setZoom(double zoom, QPointF anchor) {
  m_userMoved = true;
  zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
  const QPointF texel = toTexel(anchor);
  m_zoom = zoom;
  m_offset = anchor - texel * m_zoom;
  update();
  updateHover();
  Q_EMIT zoomChanged(m_zoom);
}

void CompareView::fitToView() {
  if (m_left.isNull())
    return;
  m_userMoved = false;
  const double contentWidth =
      m_mode == Mode::SideBySide ? 2.0 * m_left.width() + kSideGap : m_left.width();
  const double zoom = std::min(double(width()) / contentWidth, double(height()) / m_left.height());
  m_zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
  m_offset =
      QPointF((width() - contentWidth * m_zoom) / 2.0, (height() - m_left.height() * m_zoom) / 2.0);
  update();
  updateHover();
  Q_EMIT zoomChanged(m_zoom);
}

void CompareView::showActualPixels() {
  setZoom(1.0, QPointF(width() / 2.0, height() / 2.0));
}

int CompareView::dividerX() const {
  return int(std::lround(m_wipe * width()));
}

QImage CompareView::picture() {
  QImage image(size(), QImage::Format_RGB32);
  render(&image);
  return image;
}

namespace {

// A label over the picture: white on a dark chip, readable over white texels as over black.
void drawLabel(QPainter& painter, const QRectF& area, int alignment, const QString& text) {
  const QRectF bounds = painter.boundingRect(area, alignment, text);
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(0, 0, 0, 200));
  painter.drawRoundedRect(bounds.adjusted(-4, -2, 4, 2), 3, 3);
  painter.setPen(Qt::white);
  painter.drawText(area, alignment, text);
}

}  // namespace

void CompareView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(40, 40, 44));
  if (m_left.isNull()) {
    painter.setPen(Qt::white);
    painter.drawText(rect(), Qt::AlignCenter, tr("Compress a map to compare it here"));
    return;
  }
  // Above 1:1 every texel is a sharp square; below it, smoothing keeps the image readable.
  painter.setRenderHint(QPainter::SmoothPixmapTransform, m_zoom < 1.0);
  const QRectF target(toWidget(QPointF(0, 0)),
                      QSizeF(m_left.width() * m_zoom, m_left.height() * m_zoom));
  switch (m_mode) {
    case Mode::Wipe: {
      const int x = dividerX();
      painter.save();
      painter.setClipRect(QRect(0, 0, x, height()));
      painter.drawImage(target, m_left);
      painter.setClipRect(QRect(x, 0, width() - x, height()));
      painter.drawImage(target, m_right);
      painter.restore();
      painter.setPen(QPen(QColor(255, 255, 255, 210), 2));
      painter.drawLine(x, 0, x, height());
      drawLabel(painter, QRect(8, 8, std::max(0, x - 16), 20), Qt::AlignLeft, tr("Original"));
      drawLabel(painter, QRect(x + 8, 8, std::max(0, width() - x - 16), 20), Qt::AlignRight,
                tr("Compressed"));
      break;
    }
    case Mode::SideBySide: {
      painter.drawImage(target, m_left);
      painter.drawImage(target.translated((m_left.width() + kSideGap) * m_zoom, 0), m_right);
      // Above each image when there is room, otherwise over its top edge.
      const double top = std::max(target.top() - 24.0, 4.0);
      drawLabel(painter, QRectF(target.left() + 4, top, 200, 20), Qt::AlignLeft, tr("Original"));
      drawLabel(painter,
                QRectF(target.left() + (m_left.width() + kSideGap) * m_zoom + 4, top, 200, 20),
                Qt::AlignLeft, tr("Compressed"));
      break;
    }
    case Mode::Flip:
      if (m_flipMap.isNull()) {
        drawLabel(painter, rect().adjusted(8, 8, -8, -8), Qt::AlignTop | Qt::AlignLeft,
                  tr("Measuring FLIP…"));
        break;
      }
      painter.drawImage(target, m_flipMap);
      drawLabel(painter, rect().adjusted(8, 8, -8, -8), Qt::AlignTop | Qt::AlignLeft,
                tr("FLIP x %1 (mean %2): navy none, red most")
                    .arg(m_gain, 0, 'f', 0)
                    .arg(m_flipMean, 0, 'f', 4));
      break;
    case Mode::Blocks:
      painter.drawImage(target, m_difference);
      drawLabel(painter, rect().adjusted(8, 8, -8, -8), Qt::AlignTop | Qt::AlignLeft,
                tr("RMS error of each %1x%2 block x %3 (worst %4/255): navy none, red most")
                    .arg(m_blockWidth)
                    .arg(m_blockHeight)
                    .arg(m_gain, 0, 'f', 0)
                    .arg(m_worstBlock * 255.0, 0, 'f', 1));
      break;
    case Mode::Difference:
    case Mode::Threshold:
      painter.drawImage(target, m_difference);
      drawLabel(painter, rect().adjusted(8, 8, -8, -8), Qt::AlignTop | Qt::AlignLeft,
                m_mode == Mode::Difference
                    ? tr("|original - compressed| x %1").arg(m_gain, 0, 'f', 0)
                    : tr("white: differs by more than %1/255").arg(m_threshold * 255.0, 0, 'f', 0));
      break;
  }
}

void CompareView::resizeEvent(QResizeEvent*) {
  // Until the user zooms or pans, the picture follows the widget's size (it has none before the
  // dialog is first shown).
  if (!m_userMoved)
    fitToView();
}

void CompareView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  setZoom(m_zoom * std::pow(1.25, steps), event->position());
  event->accept();
}

void CompareView::mousePressEvent(QMouseEvent* event) {
  m_last = event->position();
  if (m_mode == Mode::Wipe && event->button() == Qt::LeftButton &&
      std::abs(event->position().x() - dividerX()) <= kDividerGrab) {
    m_drag = Drag::Divider;
  } else {
    m_drag = Drag::Pan;
  }
  event->accept();
}

void CompareView::mouseMoveEvent(QMouseEvent* event) {
  const QPointF pos = event->position();
  if (m_drag == Drag::Divider) {
    setWipeFraction(pos.x() / std::max(1, width()));
  } else if (m_drag == Drag::Pan) {
    m_userMoved = true;
    m_offset += pos - m_last;
    update();
  } else if (m_mode == Mode::Wipe) {
    setCursor(std::abs(pos.x() - dividerX()) <= kDividerGrab ? Qt::SplitHCursor : Qt::ArrowCursor);
  }
  m_last = pos;
  m_pointer = pos;
  updateHover();
}

void CompareView::leaveEvent(QEvent*) {
  m_pointer.reset();
  updateHover();
}

void CompareView::updateHover() {
  QString text;
  if (m_pointer && m_original && m_compressed) {
    QPointF texel = toTexel(*m_pointer);
    if (m_mode == Mode::SideBySide && texel.x() >= m_original->width() + kSideGap)
      texel.rx() -= m_original->width() + kSideGap;
    const int x = int(std::floor(texel.x())), y = int(std::floor(texel.y()));
    if (x >= 0 && y >= 0 && x < m_original->width() && y < m_original->height()) {
      text = tr("texel %1, %2: original %3, compressed %4")
                 .arg(x)
                 .arg(y)
                 .arg(texelText(*m_original, x, y), texelText(*m_compressed, x, y));
    }
  }
  Q_EMIT hoverText(text);
}

void CompareView::mouseReleaseEvent(QMouseEvent*) {
  m_drag = Drag::None;
}

}  // namespace relief::ui::inline compare
