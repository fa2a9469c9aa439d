// HeightFromColor; see HeightFromColor.h.
#include "core/generators/HeightFromColor.h"

#include "core/base/ParallelFor.h"

#include <algorithm>

namespace relief::core::inline generators {

Image heightFromColor(const Image& color, const HeightFromColorOptions& options,
                      const WorkControl& control) {
  const Image grey = luminance(color);
  const double sigma = options.highPassRadius * options.texelScale;
  const Image largeScale = sigma > 0.0 ? gaussianBlur(grey, sigma, options.edge, control) : Image();
  Image height(color.width(), color.height(), 1, ColorSpace::Linear);
  height.setSourceBitsPerChannel(16);
  const float span = float(std::max(options.levelsHigh - options.levelsLow, 1e-6));
  parallelFor(
      color.height(),
      [&](int y) {
        for (int x = 0; x < color.width(); ++x) {
          float h = grey.at(x, y, 0);
          if (sigma > 0.0)
            h = h - largeScale.at(x, y, 0) + 0.5f;
          h = (h - 0.5f) * float(options.contrast) + 0.5f;
          h = (h - float(options.levelsLow)) / span;
          h = std::clamp(h, 0.0f, 1.0f);
          height.at(x, y, 0) = options.invert ? 1.0f - h : h;
        }
      },
      control);
  return height;
}

}  // namespace relief::core::inline generators
