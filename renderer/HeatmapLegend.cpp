// HeatmapLegend; see HeatmapLegend.h.
#include "renderer/HeatmapLegend.h"

#include "core/image/Heatmap.h"

#include <QFont>
#include <QFontMetrics>
#include <QLinearGradient>
#include <QPainter>

#include <algorithm>

namespace relief::renderer {
namespace {

// Must match kMipDisplayLevels in shaders/include/debug_views.glsl.
constexpr double kMipDisplayLevels = 10.0;

QString formatValue(double value) {
  return value >= 10.0 || value == double(int(value)) ? QString::number(value, 'f', 0)
                                                      : QString::number(value, 'g', 2);
}

}  // namespace

int maxSamplesPerPixel(const core::Material& material) {
  // As material.frag counts: every sampling stage, shadows or not, so the colours of a
  // technique do not shift when shadows are toggled.
  using core::ParamId;
  return std::max(int(material.parameter(ParamId::MaxSamples)),
                  int(material.parameter(ParamId::MinSamples))) +
         1 + int(material.parameter(ParamId::RefinementSteps)) +
         int(material.parameter(ParamId::ShadowSamples));
}

std::optional<HeatmapLegend> legendFor(core::DebugView view, const core::Material& material,
                                       double errorMaxTexels) {
  switch (view) {
    case core::DebugView::Steps:
      return HeatmapLegend{QStringLiteral("height samples per pixel"),
                           double(maxSamplesPerPixel(material))};
    case core::DebugView::Mip:
      return HeatmapLegend{QStringLiteral("height map mip level"), kMipDisplayLevels};
    case core::DebugView::Error:
      return HeatmapLegend{QStringLiteral("UV error vs exact trace (texels)"), errorMaxTexels};
    default:
      return std::nullopt;
  }
}

void drawHeatmapLegend(QPainter& painter, const QRect& area, const HeatmapLegend& legend) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, false);
  QFont font = painter.font();
  font.setPixelSize(std::clamp(area.height() / 40, 10, 14));
  painter.setFont(font);
  const int margin = font.pixelSize();
  const int textHeight = font.pixelSize() + 4;
  const int titleWidth = QFontMetrics(font).horizontalAdvance(legend.title);
  const int barWidth = std::max(std::clamp(area.width() / 4, 120, 260), titleWidth);
  const int barHeight = font.pixelSize();
  const QRect box(area.right() - barWidth - 2 * margin,
                  area.bottom() - barHeight - 2 * textHeight - 2 * margin, barWidth + 2 * margin,
                  barHeight + 2 * textHeight + margin);
  painter.fillRect(box, QColor(0, 0, 0, 170));
  const QRect bar(box.left() + margin, box.top() + textHeight + margin / 2, barWidth, barHeight);
  QLinearGradient gradient(bar.topLeft(), bar.topRight());
  for (int i = 0; i <= 8; ++i) {
    const glm::vec3 c = core::heatmapColor(float(i) / 8.0f);
    gradient.setColorAt(double(i) / 8.0, QColor::fromRgbF(c.r, c.g, c.b));
  }
  painter.fillRect(bar, gradient);
  painter.setPen(Qt::white);
  painter.drawText(QRect(box.left(), box.top() + margin / 4, box.width(), textHeight),
                   Qt::AlignCenter, legend.title);
  const QRect labels(bar.left(), bar.bottom() + 2, bar.width(), textHeight);
  painter.drawText(labels, Qt::AlignLeft | Qt::AlignTop, QStringLiteral("0"));
  painter.drawText(labels, Qt::AlignHCenter | Qt::AlignTop, formatValue(legend.maximum / 2.0));
  painter.drawText(labels, Qt::AlignRight | Qt::AlignTop, formatValue(legend.maximum));
  painter.restore();
}

}  // namespace relief::renderer
