// Export as a Godot 4 StandardMaterial3D: <name>.tres next to its PNG textures (paths relative
// to the .tres, which Godot's text loader resolves against the file's own folder). Relief's
// parameters become Godot's heightmap settings as docs/export.md explains, checked against
// the code Godot 4 generates for BaseMaterial3D.
#pragma once

#include "core/base/Result.h"
#include "core/exporters/EngineConversion.h"
#include "core/preset/MaterialPreset.h"

#include <string>
#include <vector>

namespace relief::core::inline exporters {

// The result's mainPath is the .tres; its notes say what Godot cannot represent exactly (a
// height bias, Kaneko's parallax).
Result<EngineExportResult> exportGodot(const Preset& preset, const std::string& folder);

}  // namespace relief::core::inline exporters
