// OrbitCamera: the viewer's camera, orbiting a target point. Shared by the viewport, the CLI's
// render command and the tests, so that the same numbers give the same picture everywhere.
#pragma once

#include "core/mesh/Mesh.h"

#include <glm/glm.hpp>

namespace relief::core::inline view {

struct OrbitCamera {
  float yawDeg = 25.0f;    // around +Y; 0 looks from +Z toward the target
  float pitchDeg = 35.0f;  // elevation above the XZ plane; 90 looks straight down
  float distance = 3.6f;   // from the target, in world units
  float fovYDeg = 40.0f;   // vertical field of view
  glm::vec3 target{0.0f};

  static constexpr float kMinPitchDeg = -89.0f;
  static constexpr float kMaxPitchDeg = 89.0f;

  glm::vec3 position() const;
  glm::mat4 viewMatrix() const;
  glm::mat4 projectionMatrix(float aspect) const;

  void orbit(float deltaYawDeg, float deltaPitchDeg);
  // factor > 1 moves away; distance stays within sensible limits of the framed size.
  void zoom(float factor);
  // Moves the target within the view plane; dx, dy are fractions of the view height.
  void pan(float dx, float dy);
  // Centres on the bounds and moves in until they fill the view (with a margin) for a view of
  // the given aspect ratio, keeping the current angles.
  void frame(const Bounds& bounds, float aspect = kDefaultAspect);

  static constexpr float kDefaultAspect = 16.0f / 9.0f;
};

// The camera the viewport and the CLI start with for a mesh: default angles, framed on it.
OrbitCamera defaultCameraFor(const Mesh& mesh, float aspect = OrbitCamera::kDefaultAspect);

}  // namespace relief::core::inline view
