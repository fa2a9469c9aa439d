// ViewState: what the viewport shows besides the material — the mesh (by where it comes from),
// the camera, the light, the environment (image-based light, background) and the display
// transform (exposure, tone mapping). Presets store it, the viewport reports and shows it, and
// opening a preset's view is showing one. Each part may be missing (the bundled samples store no
// view); showing a state leaves what it does not say as it is, and frames the mesh when it has no
// camera.
#pragma once

#include "core/view/DirectionalLight.h"
#include "core/view/DisplayTransform.h"
#include "core/view/Environment.h"
#include "core/view/OrbitCamera.h"

#include <optional>
#include <string>

namespace relief::core::inline view {

struct ViewState {
  std::optional<OrbitCamera> camera;
  std::optional<DirectionalLight> light;
  std::string mesh;  // a primitive's name ("plane"), a mesh file's absolute path, or "" (none)
  std::optional<DisplayTransform> display;  // exposure and tone mapping
  std::optional<Environment> environment;   // image-based light and background
};

}  // namespace relief::core::inline view
