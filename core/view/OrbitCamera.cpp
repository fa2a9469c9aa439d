// OrbitCamera; see OrbitCamera.h.
#include "core/view/OrbitCamera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace relief::core::inline view {

glm::vec3 OrbitCamera::position() const {
  const float yaw = glm::radians(yawDeg);
  const float pitch = glm::radians(pitchDeg);
  const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                         std::cos(pitch) * std::cos(yaw));
  return target + distance * offset;
}

glm::mat4 OrbitCamera::viewMatrix() const {
  return glm::lookAt(position(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 OrbitCamera::projectionMatrix(float aspect) const {
  // Near and far follow the distance so depth precision stays useful at any zoom.
  const float nearPlane = std::max(0.01f, distance * 0.02f);
  const float farPlane = distance * 20.0f + 10.0f;
  return glm::perspective(glm::radians(fovYDeg), std::max(aspect, 1e-3f), nearPlane, farPlane);
}

void OrbitCamera::orbit(float deltaYawDeg, float deltaPitchDeg) {
  yawDeg = std::fmod(yawDeg + deltaYawDeg, 360.0f);
  pitchDeg = std::clamp(pitchDeg + deltaPitchDeg, kMinPitchDeg, kMaxPitchDeg);
}

void OrbitCamera::zoom(float factor) {
  distance = std::clamp(distance * factor, 0.05f, 500.0f);
}

void OrbitCamera::pan(float dx, float dy) {
  const glm::mat4 view = viewMatrix();
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
  const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
  const float viewHeight = 2.0f * distance * std::tan(glm::radians(fovYDeg) * 0.5f);
  target += (-dx * right + dy * up) * viewHeight;
}

void OrbitCamera::frame(const Bounds& bounds, float aspect) {
  target = bounds.center();
  const float margin = 1.08f;
  const float tanY = std::tan(glm::radians(fovYDeg) * 0.5f);
  const float tanX = tanY * std::max(aspect, 1e-3f);
  // Two sufficient distances; the nearer one is used. The bounding sphere fits in the narrower
  // field of view; or every box corner fits in the frustum seen from the current angles.
  const float radius = std::max(bounds.sphereRadius, 1e-3f);
  const float sphereDistance = margin * radius / std::sin(std::atan(std::min(tanX, tanY)));

  distance = 1.0f;  // only the direction matters for the basis below
  const glm::mat4 view = viewMatrix();
  float boxDistance = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 point((corner & 1) ? bounds.max.x : bounds.min.x,
                          (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 offset = point - target;
    const float x = std::abs(glm::dot(offset, glm::vec3(view[0][0], view[1][0], view[2][0])));
    const float y = std::abs(glm::dot(offset, glm::vec3(view[0][1], view[1][1], view[2][1])));
    const float towardCamera = glm::dot(offset, glm::vec3(view[0][2], view[1][2], view[2][2]));
    boxDistance =
        std::max({boxDistance, towardCamera + margin * x / tanX, towardCamera + margin * y / tanY});
  }
  distance = std::clamp(std::min(sphereDistance, boxDistance), 0.05f, 500.0f);
}

OrbitCamera defaultCameraFor(const Mesh& mesh, float aspect) {
  OrbitCamera camera;
  camera.frame(mesh.bounds(), aspect);
  return camera;
}

}  // namespace relief::core::inline view
