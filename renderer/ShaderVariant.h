// The compile-time switches of the material shader family: one program per combination of
// technique, shadow mode, UV edge, depth offset, packed height, debug view and output kind.
// Everything else is a uniform, so dragging a slider never recompiles.
#pragma once

#include "core/exporters/EnginePreview.h"
#include "core/material/Material.h"
#include "core/view/DebugView.h"
#include "renderer/FrameSettings.h"

#include <string>
#include <vector>

namespace relief::renderer {

// The #defines for material.vert/frag, in a fixed order (the list doubles as a cache key).
// `hexTiling`: the view asks for hex-tiling (HEX_TILING, where it applies; FrameSettings.h).
// `engine`: an engine preview's trace (core/exporters/EnginePreview.h), which replaces the
// technique, the self-shadowing and the view options with what the engine does.
std::vector<std::string> materialShaderDefines(const core::Material& material, core::DebugView view,
                                               FrameOutput output, bool hexTiling = false,
                                               const core::EngineTraceParams* engine = nullptr);

// Whether hex-tiling applies to this material and view (the technique, repeating UVs, not the
// error view or the eye rays).
bool hexTilingApplies(const core::Material& material, core::DebugView view, FrameOutput output);

// The #defines every material program gets from core's tables, the same in every variant (so
// built once, and not part of the cache key): VIEW_<NAME> with each debug view's number
// (core/view/DebugView.cpp's rows, which DEBUG_VIEW is compared with), and MAP_SLOT_UNIFORMS,
// the declarations of each map slot's sampler and presence flag (core/material/MapSlot.cpp's
// rows), which shaders/include/material_inputs.glsl expands. A new view or slot is then a row
// and the shader code that uses it, never a declaration kept in step by hand.
const std::vector<std::string>& materialTableDefines();

// Whether the program has the tessellation stages (material.tesc/tese) and draws patches: the
// displacement technique, except for the eye-ray output, which wants the rays' entry points on
// the undisplaced mesh (the exact tracer starts there), and engine previews (engines trace
// the relief on the flat mesh).
bool usesTessellation(const core::Material& material, FrameOutput output,
                      bool enginePreview = false);

}  // namespace relief::renderer
