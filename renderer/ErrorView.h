// The `error` view: the frame's final UV per pixel, read back in float, against the exact
// reference tracer (core/ReliefTracer) for the same eye rays. The GL passes are quick; the
// CPU trace runs wherever the caller likes (the viewport uses a worker thread).
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "core/tracing/HeightField.h"
#include "renderer/FrameSettings.h"

namespace relief::renderer {

class MaterialRenderer;

struct ErrorViewInputs {
  core::Image finalUv;  // FloatData render of the uv view
  core::Image eyeRays;  // EyeRays render
  core::HeightField field;
};

// Renders both passes with the renderer's current material (context current).
core::Result<ErrorViewInputs> renderErrorViewInputs(MaterialRenderer& renderer,
                                                    const FrameSettings& frame, int width,
                                                    int height);

}  // namespace relief::renderer
