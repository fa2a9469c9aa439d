// Ambient occlusion from a height map, horizon-based (after Bavoil & Sainz 2008): in each of
// N directions, march S steps out to a radius and find the highest horizon; the occlusion in
// that direction is the sine of the horizon's elevation. A flat field is exactly 1 (no
// occlusion); a pit sees high horizons all around.
#pragma once

#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/image/Image.h"

namespace relief::core::inline generators {

struct AmbientOcclusionOptions {
  int directions = 16;
  int steps = 16;
  double radius = 32.0;            // texels
  double depth = 16.0;             // texels that a height difference of 1.0 stands for
  double strength = 1.0;           // 0 = no occlusion, 1 = physical, more darkens further
  EdgeMode edge = EdgeMode::Wrap;  // Wrap for tileable maps
  double texelScale = 1.0;         // multiplies radius and depth (previews)
};

Image ambientOcclusionFromHeight(const Image& height, const AmbientOcclusionOptions& options,
                                 const WorkControl& control = {});

}  // namespace relief::core::inline generators
