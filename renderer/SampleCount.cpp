// SampleCount; see SampleCount.h.
#include "renderer/SampleCount.h"

#include "renderer/MaterialRenderer.h"

#include <algorithm>
#include <vector>

namespace relief::renderer {

core::Result<SampleCount> countHeightSamples(MaterialRenderer& renderer, FrameSettings frame,
                                             int width, int height) {
  frame.debugView = core::DebugView::Steps;
  frame.output = FrameOutput::FloatData;
  core::Result<core::Image> counts = renderer.renderToImage(frame, width, height);
  if (!counts)
    return core::makeError(counts.error());
  std::vector<float> samples;
  for (std::size_t p = 0; p < counts->pixelCount(); ++p) {
    const float* pixel = counts->data() + p * 4;
    if (pixel[3] > 0.5f)
      samples.push_back(pixel[0]);
  }
  SampleCount count;
  count.pixels = static_cast<long long>(samples.size());
  if (samples.empty())
    return count;
  double sum = 0.0;
  for (float s : samples)
    sum += s;
  count.mean = sum / double(samples.size());
  count.max = *std::max_element(samples.begin(), samples.end());
  const auto rank = samples.begin() + std::ptrdiff_t(samples.size() * 95 / 100);
  std::nth_element(samples.begin(), rank, samples.end());
  count.p95 = *rank;
  return count;
}

}  // namespace relief::renderer
