// Height maps from colour photographs: luminance, with the large-scale shading removed by a
// high-pass (luminance minus its Gaussian blur), then contrast, levels and optional inversion.
// A photograph's brightness is only a guess at height; this is the usual starting point artists
// then refine.
#pragma once

#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/image/Image.h"

namespace relief::core::inline generators {

struct HeightFromColorOptions {
  double highPassRadius = 64.0;  // texels (Gaussian sigma); 0 keeps the large scale
  double contrast = 1.0;         // around mid-grey
  double levelsLow = 0.0;        // input level mapped to 0
  double levelsHigh = 1.0;       // input level mapped to 1
  bool invert = false;           // dark is high (e.g. grout in a photo of tiles)
  EdgeMode edge = EdgeMode::Wrap;
  double texelScale = 1.0;  // multiplies the radius (previews)
};

Image heightFromColor(const Image& color, const HeightFromColorOptions& options,
                      const WorkControl& control = {});

}  // namespace relief::core::inline generators
