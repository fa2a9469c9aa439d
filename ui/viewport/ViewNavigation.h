// ViewNavigation: how the viewport's mouse moves the view. A drag's kind comes from its button
// and modifiers (left: orbit, Ctrl: the light, Shift or middle: pan, right: zoom; on the A/B
// divider: the divider), and a drag of (dx, dy) pixels turns into a camera or a light.
#pragma once

#include "core/view/DirectionalLight.h"
#include "core/view/OrbitCamera.h"

#include <Qt>

namespace relief::ui::inline viewport {

enum class DragMode { None, Orbit, Light, Pan, Zoom, Divider };

inline constexpr float kOrbitDegreesPerPixel = 0.4f;

DragMode dragModeFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers, bool onDivider);
// The camera after a drag of (dx, dy) pixels in a view `viewHeight` pixels high (Orbit, Pan,
// Zoom; other modes leave it).
core::OrbitCamera draggedCamera(core::OrbitCamera camera, DragMode mode, float dx, float dy,
                                int viewHeight);
// The light after a Ctrl+drag: azimuth and elevation follow the mouse, the elevation stops at
// the horizon unless `belowHorizon`.
core::DirectionalLight draggedLight(core::DirectionalLight light, float dx, float dy,
                                    bool belowHorizon);
// The camera after a wheel turn of `angleDelta` (120 a notch: about 12% closer or farther).
core::OrbitCamera wheeledCamera(core::OrbitCamera camera, int angleDelta);

}  // namespace relief::ui::inline viewport
