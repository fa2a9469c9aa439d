// Legends for the heat-map views (samples per pixel, mip level, UV error): what the colours
// mean, drawn with QPainter in the corner of a picture. The viewport paints it over its frame
// and the CLI onto the image it writes, so both show the same scale.
#pragma once

#include "core/material/Material.h"
#include "core/view/DebugView.h"

#include <QColor>
#include <QImage>
#include <QString>

#include <optional>

class QPainter;

namespace relief::renderer {

struct HeatmapLegend {
  QString title;
  double maximum = 1.0;  // the value shown in red; the ramp starts at 0
  // A colour outside the ramp and what it means (the error view's minified pixels), drawn as a
  // swatch and a line under the scale; no swatch when `note` is empty.
  QColor noteColor;
  QString note;
};

// The legend for a view, or nullopt for views that are not heat maps. `errorMaxTexels` is the
// error view's scale.
std::optional<HeatmapLegend> legendFor(core::DebugView view, const core::Material& material,
                                       double errorMaxTexels);

// Samples per pixel the steps view's red stands for: the most a pixel can take with these
// parameters (view ray, refinement and shadow ray); mirrors `most` in material.frag.
int maxSamplesPerPixel(const core::Material& material);

// Draws the ramp with its scale in the bottom-right corner of `area`.
void drawHeatmapLegend(QPainter& painter, const QRect& area, const HeatmapLegend& legend);

}  // namespace relief::renderer
