// Heatmap; see Heatmap.h.
#include "core/image/Heatmap.h"

#include <algorithm>
#include <array>

namespace relief::core::inline image {

glm::vec3 heatmapColor(float t) {
  static constexpr std::array<glm::vec3, 5> kStops = {
      glm::vec3(0.05f, 0.05f, 0.35f), glm::vec3(0.00f, 0.45f, 0.85f),
      glm::vec3(0.10f, 0.75f, 0.35f), glm::vec3(0.95f, 0.80f, 0.10f),
      glm::vec3(0.85f, 0.10f, 0.05f)};
  const float x = std::clamp(t, 0.0f, 1.0f) * float(kStops.size() - 1);
  const auto index = std::min(std::size_t(x), kStops.size() - 2);
  return glm::mix(kStops[index], kStops[index + 1], x - float(index));
}

}  // namespace relief::core::inline image
