// DirectionalLight: a light at infinity given by azimuth and elevation in world space, with a
// colour, an intensity and an ambient term (Blinn-Phong lighting, reference 004).
#pragma once

#include <glm/glm.hpp>

namespace relief::core::inline view {

struct DirectionalLight {
  // Front-right of the default camera (yaw 25) and fairly low, so relief reads clearly.
  float azimuthDeg = 75.0f;    // around +Y; 0 is toward +Z (the side the default camera is on)
  float elevationDeg = 35.0f;  // above the XZ plane; 90 is straight overhead
  glm::vec3 color{1.0f, 0.97f, 0.92f};
  float intensity = 1.0f;
  float ambient = 0.12f;  // fraction of the colour map's value lit without direction

  // Unit vector pointing from the surface toward the light.
  glm::vec3 direction() const;

  bool operator==(const DirectionalLight&) const = default;
};

}  // namespace relief::core::inline view
