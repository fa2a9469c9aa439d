// Normal maps from height maps (reference 003, section 1.4): the tangent-space normal of the
// surface z = h(u, v) is normalize(-s * dh/dx, -s * dh/dy, 1), with the gradient measured in
// texels and y pointing up the image (OpenGL convention).
#pragma once

#include "core/Image.h"

namespace relief::core {

enum class EdgeMode { Wrap, Clamp };

struct NormalFromHeightOptions {
  // Slope per unit of height per texel: a rise of 1.0 over one texel tilts the normal as a
  // slope of `strength`. For a height map whose 1.0 spans heightScale UV units on a map W
  // texels wide, strength = heightScale * W reproduces the geometry exactly.
  float strength = 1.0f;
  EdgeMode edge = EdgeMode::Wrap;  // Wrap for tileable maps
};

// Central differences on the first channel of `height`. Returns an RGB image encoding
// n * 0.5 + 0.5, linear.
Image normalMapFromHeight(const Image& height, const NormalFromHeightOptions& options);

}  // namespace relief::core
