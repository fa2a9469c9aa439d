// What each engine does with Relief's relief, declared once for the engine exports (which write
// these properties) and the viewport's engine preview modes (which trace with them), so the
// preview shows what the exported material will show (docs/export.md, docs/techniques.md).
//
// Each engine's properties are computed here in the engine's own units, exactly as the export
// writes them; engineTrace() then applies the engine's own unit rules to those values, as the
// engine's shader does, to give the trace the preview runs (shaders/include/engine_parallax.glsl).
#pragma once

#include "core/material/Material.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline exporters {

enum class Engine { Godot, Unreal, Unity, UnityHdrp };

struct EngineInfo {
  Engine engine;
  std::string_view name;   // render --engine <name>, the toolbar's tooltip
  std::string_view label;  // the toolbar's choice and the grid's captions
};

std::span<const EngineInfo> allEngines();
const EngineInfo& engineInfo(Engine engine);
std::optional<Engine> findEngine(std::string_view name);

// Godot 4 StandardMaterial3D's heightmap_* properties (GodotExport writes them).
struct GodotHeightmap {
  double scale = 0.0;  // heightmap_scale; Godot multiplies it by 0.01
  bool deepParallax = false;
  int minLayers = 8;
  int maxLayers = 32;
  bool flipTexture = false;  // heightmap_flip_texture: the map stores depth
};
GodotHeightmap godotHeightmap(const Material& material);

// The inputs of Epic's ParallaxOcclusionMapping material function (the Unreal manifest's).
struct UnrealPom {
  double heightRatio = 0.0;
  double minSteps = 1.0;
  double maxSteps = 1.0;
  double referencePlane = 1.0;  // the height (0 bottom, 1 top) that lies on the mesh
  bool pixelDepthOffset = false;
};
UnrealPom unrealPom(const Material& material);
// The Reference Plane: the height (0 bottom, 1 top) that lies on the mesh's surface. Relief's
// surface is s = h * scale + bias, so it is -bias / scale, clamped.
double unrealReferencePlane(double heightScale, double heightBias);

// URP Lit's _Parallax: ParallaxOffset1Step offsets by (h * A - A / 2) * view.xy / (view.z + 0.42),
// and this amplitude A matches Relief's offset head-on.
double urpParallaxAmplitude(double heightScale);

// HDRP Lit's pixel displacement properties (UnityExport writes them).
struct HdrpPixelDisplacement {
  double amplitudeCm = 0.0;      // _HeightPoMAmplitude
  double primitiveMetres = 1.0;  // _PPDPrimitiveLength and _PPDPrimitiveWidth
  double minSamples = 1.0;       // _PPDMinSamples
  double maxSamples = 1.0;       // _PPDMaxSamples
  double lodThreshold = 5.0;     // _PPDLodThreshold
  bool lockTilingScale = true;   // _DisplacementLockTilingScale
  bool depthOffset = false;      // _DepthOffsetEnable
};
inline constexpr int kHdrpMaxSamples = 64;  // the range HDRP's material editor allows
HdrpPixelDisplacement hdrpPixelDisplacement(const Material& material);
// _HeightPoMAmplitude (centimetres) for Relief's heightScale (texture widths), on a primitive
// whose texture spans `primitiveMetres`, the displacement scaled with the tiling (locked).
double hdrpPomAmplitudeCentimetres(double heightScale, double primitiveMetres);

// The engines' relief tracers the preview runs.
enum class EngineTrace {
  None,         // no relief: the engine shows the normal-mapped surface
  GodotOffset,  // Godot's simple parallax (offset limiting)
  GodotDeep,    // Godot's deep parallax (layers lerped by view angle, one interpolation)
  UnrealPom,    // Epic's POM function (steps lerped by view angle, one interpolation)
  UrpOffset,    // URP's ParallaxOffset1Step (one step, view.z + 0.42)
  HdrpPom,      // HDRP's pixel displacement (steps by view angle, secant refinement, LOD fade)
};

// One engine's trace in the shaders' terms, from the exported properties by the engine's rules.
struct EngineTraceParams {
  EngineTrace trace = EngineTrace::None;
  double depth = 0.0;  // full relief depth in tiled texture widths; URP: its amplitude
  double minSteps = 1.0;
  double maxSteps = 1.0;
  double referencePlane = 1.0;  // Unreal
  double lodThreshold = 0.0;    // HDRP: the mip level where the relief starts to fade
  bool depthOffset = false;     // the engine writes the relief's depth (Unreal, HDRP)
};
EngineTraceParams engineTrace(const Material& material, Engine engine);

// What the engine's material cannot show of this material's relief beyond what the export's
// notes already say: self-shadowing, which none of the exported materials has.
std::vector<std::string> engineLosses(const Material& material, Engine engine);

}  // namespace relief::core::inline exporters
