// The `error` view's numbers: for every pixel of a frame, how far (in texels) the renderer's
// final UV is from the exact intersection found by the reference tracer.
#pragma once

#include "core/image/Image.h"
#include "core/tracing/HeightField.h"

#include <atomic>
#include <functional>

namespace relief::core::inline tracing {

struct UvErrorMap {
  Image texels;       // 1 channel: error in texels; negative where the mesh is not drawn
  double mean = 0.0;  // over covered pixels
  double p95 = 0.0;
  double maximum = 0.0;
  long long pixels = 0;  // covered pixels
};

// `finalUv`: a float render of the uv view (rg = final texture UV, a > 0 where covered).
// `eyeRays`: a float render of the eye rays (rg = entry texture UV, ba = view direction xy in
// tangent space, z = sqrt(1 - x^2 - y^2)). Runs on all cores; `progress(done, total)` is
// called from worker threads now and then; `cancel` stops early (the result is then partial).
UvErrorMap computeUvErrorMap(const Image& finalUv, const Image& eyeRays, const HeightField& field,
                             const std::function<void(int done, int total)>& progress = {},
                             const std::atomic<bool>* cancel = nullptr);

// The error as heat-map colours (sRGB RGBA, alpha 0 where not covered), 0..maxTexels.
Image colorizeErrorMap(const UvErrorMap& map, double maxTexels);

// The error the heat map's top colour stands for in the viewport, the CLI and their legends: a
// quarter texel, where parallax errors start to show as swimming.
inline constexpr double kErrorDisplayTexels = 0.25;

}  // namespace relief::core::inline tracing
