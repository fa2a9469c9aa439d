// FrameSettings: everything about one frame besides the material and the mesh: the view, the
// debug view, what kind of values to write, and the optional A/B split comparison.
#pragma once

#include "core/compression/MipChain.h"
#include "core/exporters/EnginePreview.h"
#include "core/material/Material.h"
#include "core/view/DebugView.h"
#include "renderer/RenderView.h"

#include <array>
#include <optional>

namespace relief::renderer {

enum class FrameOutput {
  Display,    // sRGB colours for the screen or an 8-bit file
  FloatData,  // raw values of data views (EXR); background alpha 0 marks empty pixels
  EyeRays,    // per pixel: entry texture UV (rg) and tangent-space view direction xy (ba)
};

struct SplitComparison {
  core::Material material;       // drawn right of the divider (B); the current material is left (A)
  float dividerFraction = 0.5f;  // 0..1 of the width, from the left
};

// Looking at a material as a tile: the view's own repeats on top of the material's tiling (not
// part of the material: nothing is exported or saved), lines where the map's edges meet, and
// hex-tiling against visible repetition (shaders/include/hex_tiling.glsl; where the technique
// supports it, core::supportsHexTiling, with repeating UVs, in the shaded and data views but not
// the error view, whose exact trace reads the map as it is).
// `distance` looks at the material as from that many times farther: it repeats `distance` times
// more, so each texel covers 1/distance as many pixels and the sampler reads the mip levels an
// engine reads there (the relief's depth shrinks with the texel, as it would far away).
struct TilePreview {
  int repeats = 1;
  bool seams = false;
  bool hex = false;
  int distance = 1;
};

struct FrameSettings {
  RenderView view;
  core::DebugView debugView = core::DebugView::Shading;
  TilePreview tiles;
  // An engine preview: the relief traced as that engine's exported material traces it
  // (core/exporters/EnginePreview.h, shaders/include/engine_parallax.glsl); none: Relief's own.
  std::optional<core::Engine> engine;
  // Per slot, the mip chain an uncompressed map is sampled with: the one its compression choice
  // ships (core::shippedMipChain), built by core's filters as `compress --mips` builds it, so the
  // original and a compressed preview (which carries its own levels) differ by compression alone.
  std::array<core::MipChainSpec, core::kMapSlotCount> mipChains{};
  FrameOutput output = FrameOutput::Display;
  std::optional<SplitComparison> split;
};

// Progressive refinement of a reduced frame, as the viewport does once the input rests:
// `bands` bands of `bandRows` full-resolution rows, from the top, drawn over the stretched
// reduced frame (MaterialRenderer::renderRows and showRefined).
struct FrameRefinement {
  int bandRows = 0;
  int bands = 0;
};

}  // namespace relief::renderer
