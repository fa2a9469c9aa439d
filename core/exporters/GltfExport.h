// Export as glTF 2.0: <name>.gltf with its .bin and PNG textures, the mesh with positions,
// normals, tangents and texture coordinates, and the material as metallic-roughness (base
// colour, normal, occlusion, roughness). glTF has no parallax, so the height map and every
// Relief parameter go into the material's `extras.relief`, for tools that read them.
#pragma once

#include "core/base/Result.h"
#include "core/mesh/Mesh.h"
#include "core/preset/MaterialPreset.h"

#include <string>

namespace relief::core::inline exporters {

// Writes into `folder` (created if needed); returns the .gltf path.
Result<std::string> exportGltf(const Preset& preset, const Mesh& mesh, const std::string& folder);

}  // namespace relief::core::inline exporters
