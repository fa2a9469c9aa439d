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

std::span<const ToneMapper> allToneMappers() {
  static constexpr std::array kMappers = {ToneMapper::None, ToneMapper::PbrNeutral};
  return kMappers;
}

std::string_view toneMapperName(ToneMapper mapper) {
  return mapper == ToneMapper::PbrNeutral ? "neutral" : "none";
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

glm::vec3 applyDisplayTransform(const DisplayTransform& transform, const glm::vec3& radiance) {
  const glm::vec3 exposed = glm::max(radiance, glm::vec3(0.0f)) * transform.exposureScale();
  return transform.toneMapper == ToneMapper::PbrNeutral ? pbrNeutral(exposed) : exposed;
}

}  // namespace relief::core::inline view
