// Export for Unreal Engine: textures named and packed by Unreal's conventions (T_<name>_BaseColor,
// _Normal in DirectX's green-down convention, _ORM with occlusion, roughness and metallic in R, G
// and B, _Height), a JSON manifest that says how to import and wire them (texture settings,
// constants, and the inputs of Epic's ParallaxOcclusionMapping material function converted from
// Relief's parameters), and a Python script that does it in the Unreal Editor.
// docs/export.md gives the conversion.
#pragma once

#include "core/base/Result.h"
#include "core/exporters/EngineConversion.h"
#include "core/exporters/EnginePreview.h"
#include "core/preset/MaterialPreset.h"

#include <string>

namespace relief::core::inline exporters {

// Writes the textures, <name>_unreal.json (the result's mainPath) and <name>_unreal_import.py.
Result<EngineExportResult> exportUnreal(const Preset& preset, const std::string& folder);

}  // namespace relief::core::inline exporters
