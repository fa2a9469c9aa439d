// The rendering techniques a material can use. The names are the CLI's --technique values
// and the presets' "technique" key.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace relief::core::inline material {

enum class Technique {
  Normal,           // per-pixel normal mapping in tangent space (reference 004)
  Parallax,         // Kaneko: T + h_scaled * V.xy / V.z (references 000, 004)
  ParallaxLimited,  // Welsh's offset limiting: T + h_scaled * V.xy (references 000, 004)
  Steep,            // layered linear search, first layer below the surface, no interpolation
  Pom,              // parallax occlusion mapping as reference 001 gives it
  Relief,           // linear search, then binary refinement
  Quadtree,         // exact: maximum-mipmap traversal to the bilinear cell (Tevs et al. 2008)
  Cone,             // exact: cone steps through empty space to the bilinear cell (Dummer 2006)
  Displacement,     // tessellated geometry moved by the height: the geometric reference
};
// How many techniques there are (the last one + 1): Technique.cpp's table has a row for each.
inline constexpr std::size_t kTechniqueCount = std::size_t(Technique::Displacement) + 1;

// Whether the technique marches along the view ray (and so can self-shadow and has a cost
// that depends on the sample counts).
bool isMarchingTechnique(Technique technique);

// Whether the technique walks to the exact intersection with the bilinear field (quadtree,
// cone), as far as the ray needs, so the sample counts do not apply.
bool isExactTracing(Technique technique);

// Whether the relief occludes itself (a marching technique, or displaced geometry): exports
// ask the engine for its occlusion parallax then, not for the plain offset.
bool isOccludingRelief(Technique technique);

// Whether hex-tiling (the view's anti-repetition, shaders/include/hex_tiling.glsl) can apply:
// not to the exact tracers, whose cone map and max-mip pyramid describe the map as it is, nor
// to displacement, whose tessellation reads the map directly.
bool supportsHexTiling(Technique technique);

std::span<const Technique> allTechniques();
std::string_view techniqueName(Technique technique);
std::string_view techniqueLabel(Technique technique);
// The #define that selects the technique's code in the shaders ("TECHNIQUE_POM").
std::string_view techniqueShaderDefine(Technique technique);
std::optional<Technique> findTechnique(std::string_view name);

}  // namespace relief::core::inline material
