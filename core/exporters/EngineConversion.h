// How Relief's Blinn-Phong surface translates to the metallic-roughness model of glTF and
// engines (documented in docs/export.md). Blinn-Phong with exponent n matches a microfacet
// distribution of alpha^2 = 2 / (n + 2) (Walter et al. 2007); glTF and Godot take perceptual
// roughness r with alpha = r^2.
#pragma once

#include "core/image/Image.h"

namespace relief::core::inline exporters {

double roughnessFromShininess(double shininess);

// A normal map in the OpenGL convention (+Y up), converting a DirectX one if needed.
Image openGlNormalMap(const Image& normals, bool yDown);

}  // namespace relief::core::inline exporters
