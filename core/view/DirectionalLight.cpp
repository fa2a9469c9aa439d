// DirectionalLight; see DirectionalLight.h.
#include "core/view/DirectionalLight.h"

#include <cmath>

namespace relief::core::inline view {

glm::vec3 DirectionalLight::direction() const {
  const float azimuth = glm::radians(azimuthDeg);
  const float elevation = glm::radians(elevationDeg);
  return glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                   std::cos(elevation) * std::cos(azimuth));
}

}  // namespace relief::core::inline view
