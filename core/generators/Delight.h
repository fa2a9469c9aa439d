// Removing the light baked into a photograph, the first step from a photo to an albedo (as
// Materialize's and Substance B2M's delighting do): the large-scale luminance, a Gaussian blur
// of the texels' linear luminance wider than the surface's own detail, is taken for the shading
// that lit the surface, and every texel is divided by it relative to its mean. Broad gradients
// and soft shadows flatten; detail smaller than the radius stays. Works in linear light and
// keeps the input's colour space and alpha.
#pragma once

#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/image/Image.h"

namespace relief::core::inline generators {

struct DelightOptions {
  double radius = 64.0;   // texels (Gaussian sigma): light that varies more slowly is removed
  double strength = 1.0;  // 0 keeps the photo, 1 divides the estimated light out entirely
  EdgeMode edge = EdgeMode::Wrap;
  double texelScale = 1.0;  // multiplies the radius (previews)
};

struct DelightResult {
  Image albedo;
  // The estimated light relative to its mean: its lowest and highest value and its RMS
  // departure from 1 (what was divided out, at strength 1).
  double lightLow = 1.0, lightHigh = 1.0, lightRms = 0.0;
};

DelightResult delight(const Image& color, const DelightOptions& options,
                      const WorkControl& control = {});

}  // namespace relief::core::inline generators
