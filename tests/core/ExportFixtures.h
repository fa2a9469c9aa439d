// The material the export tests write: small analytic maps whose texels each engine's packing
// can be checked against, and a fresh scratch folder per test.
#pragma once

#include "core/preset/MaterialPreset.h"

#include <string>

namespace relief::core {

// An empty folder under the test scratch folder.
std::string freshFolder(const std::string& name);

// A 16x16 material: a colour ramp, a DirectX-convention normal map that tilts towards +x (green
// 0.25, so 0.75 in OpenGL's convention), a height ramp, an AO map from 0.5 to 1 down the image;
// POM with heightScale 0.06, heightBias -0.06, 12/48 samples, tiling 2, shininess 2
// (roughness 0.5^0.25), normal strength 0.8. No roughness map.
Preset syntheticPreset();

}  // namespace relief::core
