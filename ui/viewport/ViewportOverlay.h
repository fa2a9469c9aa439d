// ViewportOverlay: what the viewport paints over its frame with QPainter: the error view's heat
// map (or a note while it is traced) and its numbers, a debug view's heat-map legend, the A/B
// divider with its two labels, and which engine a preview traces as.
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
  QString engineLabel;  // an engine preview's caption, bottom left; empty: Relief's own

  bool isEmpty() const { return !errorView && !legend && dividerX < 0 && engineLabel.isEmpty(); }
};

void paintViewportOverlay(QPainter& painter, const QRect& area, const ViewportOverlay& overlay);

}  // namespace relief::ui::inline viewport
