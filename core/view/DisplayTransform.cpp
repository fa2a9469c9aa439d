// DisplayTransform; see DisplayTransform.h.
#include "core/view/DisplayTransform.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace relief::core::inline view {

float DisplayTransform::exposureScale() const {
  return std::exp2(exposureEv);
}

namespace {

struct ToneMapperInfo {
  ToneMapper mapper;
  std::string_view name;
  std::string_view label;
};

constexpr std::array kToneMappers = {
    ToneMapperInfo{ToneMapper::None, "none", "None (clip)"},
    ToneMapperInfo{ToneMapper::PbrNeutral, "neutral", "Khronos PBR Neutral"},
    ToneMapperInfo{ToneMapper::Aces, "aces", "ACES filmic"},
};
constexpr std::array kToneMapperList = {ToneMapper::None, ToneMapper::PbrNeutral, ToneMapper::Aces};

}  // namespace

std::span<const ToneMapper> allToneMappers() {
  return kToneMapperList;
}

std::string_view toneMapperName(ToneMapper mapper) {
  return kToneMappers[std::size_t(mapper)].name;
}

std::string_view toneMapperLabel(ToneMapper mapper) {
  return kToneMappers[std::size_t(mapper)].label;
}

std::optional<ToneMapper> findToneMapper(std::string_view name) {
  for (ToneMapper mapper : allToneMappers()) {
    if (toneMapperName(mapper) == name)
      return mapper;
  }
  return std::nullopt;
}

glm::vec3 pbrNeutral(const glm::vec3& color) {
  // The specification's constants: F90 = 0.04 (the Fresnel of IOR 1.5), Ks = 0.8 - F90 where
  // highlight compression starts, Kd = 0.15 the speed of desaturation.
  constexpr float kF90 = 0.04f;
  constexpr float kStart = 0.8f - kF90;
  constexpr float kDesaturation = 0.15f;
  const float darkest = std::min({color.r, color.g, color.b});
  const float offset = darkest <= 2.0f * kF90 ? darkest - darkest * darkest / (4.0f * kF90) : kF90;
  const glm::vec3 lowered = color - offset;
  const float peak = std::max({lowered.r, lowered.g, lowered.b});
  if (peak <= kStart)
    return lowered;
  const float newPeak = 1.0f - (1.0f - kStart) * (1.0f - kStart) / (peak + 1.0f - 2.0f * kStart);
  const float keep = 1.0f / (kDesaturation * (peak - newPeak) + 1.0f);
  return lowered * (newPeak / peak) * keep + glm::vec3(newPeak) * (1.0f - keep);
}

glm::vec3 acesFilmic(const glm::vec3& color) {
  // Rows: sRGB to ACEScg with the reference rendering's saturation folded in, and back with the
  // output transform's (BakingLab ACES.hlsl). Each row sums to 1, so greys stay grey.
  constexpr float kIn[3][3] = {{0.59719f, 0.35458f, 0.04823f},
                               {0.07600f, 0.90834f, 0.01566f},
                               {0.02840f, 0.13383f, 0.83777f}};
  constexpr float kOut[3][3] = {{1.60475f, -0.53108f, -0.07367f},
                                {-0.10208f, 1.10813f, -0.00605f},
                                {-0.00327f, -0.07276f, 1.07602f}};
  const glm::vec3 exposed = color / 0.6f;
  glm::vec3 curved;
  for (int row = 0; row < 3; ++row) {
    const float v = kIn[row][0] * exposed.r + kIn[row][1] * exposed.g + kIn[row][2] * exposed.b;
    // The fit of the reference rendering and output transforms' tone curve.
    curved[row] =
        (v * (v + 0.0245786f) - 0.000090537f) / (v * (0.983729f * v + 0.4329510f) + 0.238081f);
  }
  glm::vec3 result;
  for (int row = 0; row < 3; ++row)
    result[row] = kOut[row][0] * curved.r + kOut[row][1] * curved.g + kOut[row][2] * curved.b;
  return glm::clamp(result, glm::vec3(0.0f), glm::vec3(1.0f));
}

glm::vec3 applyDisplayTransform(const DisplayTransform& transform, const glm::vec3& radiance) {
  const glm::vec3 exposed = glm::max(radiance, glm::vec3(0.0f)) * transform.exposureScale();
  switch (transform.toneMapper) {
    case ToneMapper::PbrNeutral:
      return pbrNeutral(exposed);
    case ToneMapper::Aces:
      return acesFilmic(exposed);
    case ToneMapper::None:
      break;
  }
  return exposed;
}

}  // namespace relief::core::inline view
