// Height samples per pixel: the steps view's float output (samples in red, coverage in alpha)
// summed over the covered pixels, for `relief-cli render --stats` and the viewport's status bar.
#pragma once

#include "core/base/Result.h"
#include "renderer/FrameSettings.h"

namespace relief::renderer {

class MaterialRenderer;

struct SampleCount {
  double mean = 0.0;
  double p95 = 0.0;
  double max = 0.0;
  long long pixels = 0;  // covered pixels
};

// Renders `frame` as the steps view (float output) at the size and counts. Needs the renderer's
// context current; leaves the framebuffer binding at 0.
core::Result<SampleCount> countHeightSamples(MaterialRenderer& renderer, FrameSettings frame,
                                             int width, int height);

}  // namespace relief::renderer
