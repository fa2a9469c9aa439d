// ImagePairView; see ImagePairView.h.
#include "ui/compare/ImagePairView.h"

#include <QPainter>

namespace relief::ui::inline compare {

ImagePairView::ImagePairView(QWidget* parent) : QWidget(parent) {
  setMinimumHeight(160);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
}

void ImagePairView::setLeft(const QImage& image, const QString& caption) {
  m_left = image;
  m_leftCaption = caption;
  update();
}

void ImagePairView::setRight(const QImage& image, const QString& caption) {
  m_right = image;
  m_rightCaption = caption;
  update();
}

void ImagePairView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().base());
  const int captionHeight = fontMetrics().height() + 4;
  const int half = width() / 2;
  const auto drawHalf = [&](const QImage& image, const QString& caption, int left) {
    const QRect area(left + 4, captionHeight, half - 8, height() - captionHeight - 4);
    painter.setPen(palette().color(QPalette::Text));
    painter.drawText(QRect(left, 0, half, captionHeight), Qt::AlignCenter, caption);
    if (image.isNull()) {
      painter.drawText(area, Qt::AlignCenter, tr("—"));
      return;
    }
    QSize size = image.size().scaled(area.size(), Qt::KeepAspectRatio);
    const QRect target(area.center().x() - size.width() / 2, area.center().y() - size.height() / 2,
                       size.width(), size.height());
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    painter.drawImage(target, image);
  };
  drawHalf(m_left, m_leftCaption, 0);
  drawHalf(m_right, m_rightCaption, half);
}

}  // namespace relief::ui::inline compare
