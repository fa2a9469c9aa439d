// The colour ramp of Relief's heat-map views (samples per pixel, mip level, UV error): navy,
// blue, green, yellow, red. Output values are sRGB-encoded display colours. shaders/include/
// heatmap.glsl mirrors these control points; keep the two in step.
#pragma once

#include <glm/glm.hpp>

namespace relief::core::inline image {

// t in [0, 1] (clamped).
glm::vec3 heatmapColor(float t);

}  // namespace relief::core::inline image
