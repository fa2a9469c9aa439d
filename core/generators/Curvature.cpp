// Curvature; see Curvature.h.
#include "core/generators/Curvature.h"

#include "core/base/ParallelFor.h"

#include <algorithm>

namespace relief::core::inline generators {

Image curvatureMap(const Image& source, const CurvatureOptions& options,
                   const WorkControl& control) {
  const double sigma = options.blurRadius * options.texelScale;
  const Image smoothed = sigma > 0.0 ? gaussianBlur(source, sigma, options.edge, control) : source;
  const int width = source.width(), height = source.height();
  Image curvature(width, height, 1, ColorSpace::Linear);
  curvature.setSourceBitsPerChannel(16);
  // Curvature is per texel of this image. A preview at texelScale of the full resolution sees
  // each feature on fewer texels: second derivatives (height) grow by 1/texelScale^2, first
  // derivatives of normals by 1/texelScale; the scale factors below undo that.
  const float gain = float(options.strength);
  const auto at = [&](int x, int y, int c) {
    return smoothed.at(edgeIndex(x, width, options.edge), edgeIndex(y, height, options.edge), c);
  };
  if (options.source == CurvatureSource::Height) {
    const float scale = float(options.texelScale * options.texelScale);
    parallelFor(
        height,
        [&](int y) {
          for (int x = 0; x < width; ++x) {
            const float laplacian = at(x - 1, y, 0) + at(x + 1, y, 0) + at(x, y - 1, 0) +
                                    at(x, y + 1, 0) - 4.0f * at(x, y, 0);
            // A dome has a negative Laplacian: convex shows bright.
            curvature.at(x, y, 0) = std::clamp(0.5f - gain * laplacian * scale, 0.0f, 1.0f);
          }
        },
        control);
    return curvature;
  }
  const float ySign = options.convention == NormalConvention::DirectX ? -1.0f : 1.0f;
  const int yChannel = std::min(1, source.channels() - 1);
  const float scale = float(options.texelScale);
  parallelFor(
      height,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          // Normals tilt outward over a dome: nx grows with x and ny (y up) grows upward, while
          // rows grow downward. Central differences of the decoded n = 2c - 1: (2 dc) / 2 = dc.
          const float dnx = at(x + 1, y, 0) - at(x - 1, y, 0);
          const float dny = (at(x, y - 1, yChannel) - at(x, y + 1, yChannel)) * ySign;
          curvature.at(x, y, 0) = std::clamp(0.5f + gain * (dnx + dny) * scale, 0.0f, 1.0f);
        }
      },
      control);
  return curvature;
}

}  // namespace relief::core::inline generators
