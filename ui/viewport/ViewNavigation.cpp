// ViewNavigation; see ViewNavigation.h.
#include "ui/viewport/ViewNavigation.h"

#include <algorithm>
#include <cmath>

namespace relief::ui::inline viewport {

DragMode dragModeFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers, bool onDivider) {
  switch (button) {
    case Qt::LeftButton:
      if (onDivider)
        return DragMode::Divider;
      if (modifiers & Qt::ControlModifier)
        return DragMode::Light;
      return modifiers & Qt::ShiftModifier ? DragMode::Pan : DragMode::Orbit;
    case Qt::MiddleButton:
      return DragMode::Pan;
    case Qt::RightButton:
      return DragMode::Zoom;
    default:
      return DragMode::None;  // other buttons do nothing
  }
}

core::OrbitCamera draggedCamera(core::OrbitCamera camera, DragMode mode, float dx, float dy,
                                int viewHeight) {
  const float height = float(std::max(viewHeight, 1));
  if (mode == DragMode::Orbit)
    camera.orbit(-dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel);
  else if (mode == DragMode::Pan)
    camera.pan(dx / height, dy / height);
  else if (mode == DragMode::Zoom)
    camera.zoom(std::exp(dy * 0.01f));
  return camera;
}

core::DirectionalLight draggedLight(core::DirectionalLight light, float dx, float dy,
                                    bool belowHorizon) {
  light.azimuthDeg = std::fmod(light.azimuthDeg - dx * kOrbitDegreesPerPixel + 360.0f, 360.0f);
  light.elevationDeg = std::clamp(light.elevationDeg - dy * kOrbitDegreesPerPixel,
                                  belowHorizon ? -90.0f : 0.0f, 90.0f);
  return light;
}

core::OrbitCamera wheeledCamera(core::OrbitCamera camera, int angleDelta) {
  camera.zoom(std::exp(-float(angleDelta) / 120.0f * 0.12f));
  return camera;
}

}  // namespace relief::ui::inline viewport
