// RenderView: everything about a frame that is not the material: camera, light, environment
// (pbr shading's image-based light, and the background), and how radiance becomes display
// colour (exposure, tone mapping).
#pragma once

#include "core/view/DirectionalLight.h"
#include "core/view/DisplayTransform.h"
#include "core/view/Environment.h"
#include "core/view/OrbitCamera.h"

#include <glm/glm.hpp>

namespace relief::renderer {

struct RenderView {
  core::OrbitCamera camera;
  core::DirectionalLight light;
  core::DisplayTransform display;
  core::Environment environment;
  // The plain-colour background (core::Background::Color).
  glm::vec3 backgroundTop{0.050f, 0.052f, 0.058f};     // linear RGB
  glm::vec3 backgroundBottom{0.012f, 0.012f, 0.014f};  // linear RGB
};

}  // namespace relief::renderer
