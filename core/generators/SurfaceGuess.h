// Guessing roughness and metallic maps from a photograph's colour (and its height), the way
// Materialize and Substance's B2M make them: rules an artist can read and adjust, not physics.
//
// Roughness: the texel's linear luminance, placed between the image's own 5th and 95th
// percentiles, runs from `roughest` (dark) to `smoothest` (bright): in a photo, the bright parts
// of a surface are mostly its exposed, worn, polished tops, the dark parts its dusty pores.
// Saturated colour (paint, glaze) can be made smoother or rougher, and with a height map the
// cavities (concave texels, from the Laplacian of the height blurred over a radius) rougher and
// the ridges smoother.
//
// Metallic: a texel is metal where its luminance and its saturation both fall in the given
// ranges (soft-edged): bare metals are bright (linear albedo above about 0.5), steel and
// aluminium grey, gold and copper saturated, so the saturation range decides which.
#pragma once

#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/image/Image.h"

namespace relief::core::inline generators {

struct RoughnessGuessOptions {
  double roughest = 0.9;      // roughness of the darkest texels (5th percentile of luminance)
  double smoothest = 0.45;    // roughness of the brightest (95th percentile)
  double saturation = 0.0;    // -1..1: a fully saturated texel this much smoother (+) or rougher
  double cavity = 0.3;        // 0..1: how much rougher a deep cavity gets (smoother a ridge)
  double cavityRadius = 2.0;  // texels: the height is blurred over this before the Laplacian
  EdgeMode edge = EdgeMode::Wrap;
  double texelScale = 1.0;  // previews: multiplies the radius
};

struct MetallicGuessOptions {
  double brightnessLow = 0.5;  // linear luminance range of metal texels
  double brightnessHigh = 1.0;
  double saturationLow = 0.0;  // saturation (HSV, of the stored colour) range of metal texels
  double saturationHigh = 0.25;
  double softness = 0.05;  // width of the soft edge of both ranges
};

struct SurfaceGuess {
  Image map;                                 // one channel, linear
  double low = 0.0, high = 0.0, mean = 0.0;  // of the result
  double metalFraction = 0.0;                // metallic: texels above 0.5
};

// `height` may be null (no cavity term); when given it must have the colour's size.
SurfaceGuess guessRoughness(const Image& color, const Image* height,
                            const RoughnessGuessOptions& options, const WorkControl& control = {});
SurfaceGuess guessMetallic(const Image& color, const MetallicGuessOptions& options,
                           const WorkControl& control = {});

}  // namespace relief::core::inline generators
