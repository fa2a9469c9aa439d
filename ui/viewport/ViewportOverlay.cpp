// ViewportOverlay; see ViewportOverlay.h.
#include "ui/viewport/ViewportOverlay.h"

#include "core/tracing/UvErrorMap.h"

#include <QCoreApplication>
#include <QImage>
#include <QPainter>
#include <QRect>

#include <algorithm>

namespace relief::ui::inline viewport {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("ViewportOverlay", text);
}

}  // namespace

void paintViewportOverlay(QPainter& painter, const QRect& area, const ViewportOverlay& overlay) {
  const QRect textArea = area.adjusted(12, 12, -12, -12);
  if (overlay.errorView) {
    if (overlay.errorImage && !overlay.errorImage->isNull()) {
      painter.drawImage(area, *overlay.errorImage);
    } else {
      painter.setPen(Qt::white);
      painter.drawText(textArea, Qt::AlignTop | Qt::AlignLeft,
                       tr("Tracing the exact intersections…"));
    }
    if (overlay.errorMap) {
      painter.setPen(Qt::white);
      painter.drawText(textArea, Qt::AlignTop | Qt::AlignLeft | Qt::TextWordWrap,
                       tr("UV error against the exact trace: %1")
                           .arg(QString::fromStdString(core::describeUvError(*overlay.errorMap))));
    }
  }
  if (overlay.legend)
    renderer::drawHeatmapLegend(painter, area, *overlay.legend);
  if (!overlay.caption.isEmpty()) {
    // On a dark band, so the caption reads over any material.
    const int height = painter.fontMetrics().height() + 8;
    const int width = painter.fontMetrics().horizontalAdvance(overlay.caption) + 16;
    const QRect band(area.left() + 8, area.bottom() - height - 8, width, height);
    painter.fillRect(band, QColor(0, 0, 0, 160));
    painter.setPen(QColor(255, 214, 120));
    painter.drawText(band, Qt::AlignCenter, overlay.caption);
  }
  if (overlay.dividerX >= 0) {
    const int x = overlay.dividerX;
    painter.setPen(QPen(QColor(255, 255, 255, 200), 2));
    painter.drawLine(x, area.top(), x, area.bottom());
    painter.setPen(Qt::white);
    painter.drawText(QRect(8, 8, std::max(x - 16, 0), 20), Qt::AlignLeft, overlay.leftLabel);
    painter.drawText(QRect(x + 8, 8, std::max(area.width() - x - 16, 0), 20), Qt::AlignRight,
                     overlay.rightLabel);
  }
}

}  // namespace relief::ui::inline viewport
