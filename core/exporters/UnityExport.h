// Export for Unity's Lit shaders: a .mat with its .meta and the textures with theirs, named and
// packed as the render pipeline reads them, so dropping the folder into Assets/ gives a working
// material. URP Lit: metallic/smoothness map (R metallic, A smoothness), occlusion map, normal
// map, height map with its single-step parallax. HDRP Lit: mask map (R metallic, G occlusion,
// B detail mask, A smoothness), normal map, height map with pixel displacement (HDRP's POM).
// docs/export.md derives the parallax conversions from the pipelines' shader code.
#pragma once

#include "core/base/Result.h"
#include "core/exporters/EngineConversion.h"
#include "core/exporters/EnginePreview.h"
#include "core/preset/MaterialPreset.h"

#include <string>

namespace relief::core::inline exporters {

enum class UnityPipeline { Urp, Hdrp };

// Writes <folder>/<name>.mat, <name>_<map>.png and a .meta for each (GUIDs stable per name).
Result<EngineExportResult> exportUnity(const Preset& preset, const std::string& folder,
                                       UnityPipeline pipeline);

}  // namespace relief::core::inline exporters
