// How Relief's material translates to the metallic-roughness model of glTF and the engines
// (documented in docs/export.md). Blinn-Phong with exponent n matches a microfacet
// distribution of alpha^2 = 2 / (n + 2) (Walter et al. 2007); glTF, Godot, Unreal and Unity take
// perceptual roughness r with alpha = r^2 (Unity stores smoothness 1 - r).
#pragma once

#include "core/image/Image.h"
#include "core/material/Material.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline exporters {

// What an engine export wrote and what the engine cannot show exactly.
struct EngineExportResult {
  std::string mainPath;            // the .tres, the .mat or the manifest
  std::vector<std::string> notes;  // for the user: the dialog and the CLI's "note:" lines
};

// The metallic-roughness constants the viewport shows: under pbr shading the metallic and
// roughness parameters, under classic the Blinn-Phong equivalent (core/shading/Brdf.h's
// roughnessFromShininess) and
// no metal.
double exportedMetallic(const Material& material);
double exportedRoughness(const Material& material);
// Whether the material shades with metallic-roughness (shading = pbr): its roughness map is then
// multiplied by the roughness factor, as glTF's is.
bool shadesPbr(const Material& material);

// A normal map in the OpenGL convention (+Y up), converting a DirectX one if needed.
Image openGlNormalMap(const Image& normals, bool yDown);

// A normal map in the DirectX convention (+Y down, Unreal's), converting an OpenGL one if needed.
Image directXNormalMap(const Image& normals, bool yDown);

// The height map as engines read it, white the top: a depth map (heightIsDepth) is inverted.
Image engineHeightMap(const Image& height, bool heightIsDepth);

// Whether the export should carry the relief: a technique other than normal mapping and a
// height map.
bool exportsParallax(const Material& material);

// Maps that share one packed texture at the size of the largest of them: the slots may hold
// maps of different sizes (an AO baked at 1K beside a 2K roughness). Element i is the resized
// copy of maps[i], or nullopt when maps[i] is null or already that size.
std::vector<std::optional<Image>> resizedToLargest(const std::vector<const Image*>& maps);

// One of packLayouts()'s layouts ("orm", "unity-mask", "unity-metallic") filled from the
// material's AO, roughness and metallic maps. A missing roughness or metallic map takes the
// material's constant (exportedRoughness, exportedMetallic), a missing AO map 1; the roughness
// and metallic maps are baked with their factors (engines' mask maps carry no factor).
// nullopt when the material has none of the maps: the engine's constants then say it all.
std::optional<Image> packEngineMasks(const Material& material, std::string_view layoutName);

// Stable 128-bit identifiers as 32 hex digits (Unity's asset GUIDs), from a name: exporting the
// same material again keeps the references a Unity project already holds.
std::string stableGuid(std::string_view name);

// A number as the engines' text formats write it: shortest round-trip-safe "%.6g".
std::string engineNumber(double value);

}  // namespace relief::core::inline exporters
