// HeatmapLegend; see HeatmapLegend.h.
#include "renderer/HeatmapLegend.h"

#include "core/image/Heatmap.h"
#include "core/tracing/UvErrorMap.h"

#include <QFont>
#include <QFontMetrics>
#include <QLinearGradient>
#include <QPainter>

#include <algorithm>
#include <cmath>

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
  switch (core::debugViewScale(view)) {
    case core::ViewScale::SamplesPerPixel:
      return HeatmapLegend{QStringLiteral("height samples per pixel"),
                           double(maxSamplesPerPixel(material)), QColor(), QString()};
    case core::ViewScale::MipLevel:
      return HeatmapLegend{QStringLiteral("height map mip level"), kMipDisplayLevels, QColor(),
                           QString()};
    case core::ViewScale::UvErrorTexels: {
      const int grey = int(std::lround(core::kErrorMinifiedGrey * 255.0f));
      return HeatmapLegend{QStringLiteral("UV error vs exact trace (texels)"), errorMaxTexels,
                           QColor(grey, grey, grey),
                           QStringLiteral("map minified (mip level %1 or more): not counted")
                               .arg(double(core::kErrorMaxMipLevel))};
    }
    case core::ViewScale::None:
      return std::nullopt;
  }
  return std::nullopt;  // not reached: every scale is handled above
}

void drawHeatmapLegend(QPainter& painter, const QRect& area, const HeatmapLegend& legend) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, false);
  QFont font = painter.font();
  font.setPixelSize(std::clamp(area.height() / 40, 10, 14));
  painter.setFont(font);
  const int margin = font.pixelSize();
  const int textHeight = font.pixelSize() + 4;
  const QFontMetrics metrics(font);
  const int barHeight = font.pixelSize();
  const bool hasNote = !legend.note.isEmpty();
  const int noteWidth =
      hasNote ? barHeight + margin / 2 + metrics.horizontalAdvance(legend.note) : 0;
  const int barWidth = std::max(
      {std::clamp(area.width() / 4, 120, 260), metrics.horizontalAdvance(legend.title), noteWidth});
  const int noteHeight = hasNote ? textHeight : 0;
  const QRect box(area.right() - barWidth - 2 * margin,
                  area.bottom() - barHeight - 2 * textHeight - noteHeight - 2 * margin,
                  barWidth + 2 * margin, barHeight + 2 * textHeight + noteHeight + margin);
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
  if (hasNote) {
    const QRect swatch(bar.left(), labels.bottom() + 2, barHeight, barHeight);
    painter.fillRect(swatch, legend.noteColor);
    painter.drawText(QRect(swatch.right() + margin / 2, swatch.top() - 2, barWidth, textHeight),
                     Qt::AlignLeft | Qt::AlignTop, legend.note);
  }
  painter.restore();
}

}  // namespace relief::renderer
