// DisplayTransform: how scene radiance becomes a display colour: an exposure in EV (stops: each
// doubles the radiance), then a tone mapper, then the sRGB encoding. The float outputs (EXR,
// the error view) stay the scene radiance before it.
//
// Tone mappers: `none` clips at 1 (the look classic shading was tuned for); `neutral` is the
// Khronos PBR Neutral tone mapper (Khronos Group, 2024, github.com/KhronosGroup/ToneMapping,
// PBR_Neutral/README.md), made for product and material views: below 0.76 it only lifts the
// darkest channel's floor (colours stay as authored), above it compresses highlights smoothly
// toward 1 and desaturates them. `aces` is the ACES filmic look (the Academy's reference
// rendering and sRGB output transforms) as Stephen Hill's fit gives it (the matrices and the
// rational curve of BakingLab's ACES.hlsl), after the 1/0.6 exposure the glTF Sample Viewer and
// three.js apply so mid-grey keeps its brightness: the film look engines ship by default
// (Unreal's, Unity HDRP's), with more contrast and hue shifts in saturated highlights than
// neutral. The shader's versions are in shaders/include/display.glsl.
#pragma once

#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string_view>

namespace relief::core::inline view {

enum class ToneMapper { None, PbrNeutral, Aces };  // the shader's uToneMapper: 0, 1, 2

struct DisplayTransform {
  static constexpr float kMinExposureEv = -10.0f;
  static constexpr float kMaxExposureEv = 10.0f;
  float exposureEv = 0.0f;
  ToneMapper toneMapper = ToneMapper::None;

  float exposureScale() const;  // 2^exposureEv
  bool operator==(const DisplayTransform&) const = default;
};

std::span<const ToneMapper> allToneMappers();
std::string_view toneMapperName(ToneMapper mapper);   // "none", "neutral", "aces"
std::string_view toneMapperLabel(ToneMapper mapper);  // "None (clip)", ...
std::optional<ToneMapper> findToneMapper(std::string_view name);

// Khronos PBR Neutral of a non-negative linear Rec. 709 colour: linear, in [0, 1].
glm::vec3 pbrNeutral(const glm::vec3& color);
// ACES filmic (Hill's fit, with the 1/0.6 exposure) of a non-negative linear Rec. 709 colour:
// linear, in [0, 1].
glm::vec3 acesFilmic(const glm::vec3& color);
// Exposure then the tone mapper (not the sRGB encoding), of linear radiance.
glm::vec3 applyDisplayTransform(const DisplayTransform& transform, const glm::vec3& radiance);

}  // namespace relief::core::inline view
