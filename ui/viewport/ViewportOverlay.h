// ViewportOverlay: what the viewport paints over its frame with QPainter: the error view's heat
// map (or a note while it is traced) and its numbers, a debug view's heat-map legend, the A/B
// divider with its two labels, which engine a preview traces as and how far the view looks from.
#pragma once

#include "renderer/HeatmapLegend.h"

#include <QString>

#include <optional>

class QImage;
class QPainter;
class QRect;

namespace relief::core::inline tracing {
struct UvErrorMap;
}

namespace relief::ui::inline viewport {

struct ViewportOverlay {
  bool errorView = false;
  const QImage* errorImage = nullptr;          // the error view's heat map; null while it is traced
  const core::UvErrorMap* errorMap = nullptr;  // its numbers, once traced
  std::optional<renderer::HeatmapLegend> legend;
  int dividerX = -1;  // -1: no divider
  QString leftLabel, rightLabel;
  // Bottom left: an engine preview's caption and the view distance; empty: Relief's own, near.
  QString caption;

  bool isEmpty() const { return !errorView && !legend && dividerX < 0 && caption.isEmpty(); }
};

void paintViewportOverlay(QPainter& painter, const QRect& area, const ViewportOverlay& overlay);

}  // namespace relief::ui::inline viewport
