// AmbientOcclusion; see AmbientOcclusion.h.
#include "core/generators/AmbientOcclusion.h"

#include "core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace relief::core {

Image ambientOcclusionFromHeight(const Image& height, const AmbientOcclusionOptions& options,
                                 const WorkControl& control) {
  const int width = height.width(), rows = height.height(), channels = height.channels();
  const int directions = std::max(options.directions, 1);
  const int steps = std::max(options.steps, 1);
  const double radius = std::max(options.radius * options.texelScale, 1.0);
  const float depth = float(options.depth * options.texelScale);

  // Every (direction, step) as an integer texel offset and its distance: nearest-texel
  // sampling keeps the inner loop to one load (1e9 samples at 2048^2 x 16 x 16).
  struct Tap {
    int dx, dy;
    float inverseDistance;
  };
  std::vector<Tap> taps;
  taps.reserve(std::size_t(directions * steps));
  for (int d = 0; d < directions; ++d) {
    const double angle = 2.0 * std::numbers::pi * (d + 0.5) / directions;
    for (int s = 1; s <= steps; ++s) {
      const double t = radius * s / steps;
      const int dx = int(std::lround(std::cos(angle) * t));
      const int dy = int(std::lround(std::sin(angle) * t));
      const double distance = std::hypot(dx, dy);
      taps.push_back({dx, dy, distance > 0.0 ? float(1.0 / distance) : 0.0f});
    }
  }
  const int margin = int(std::ceil(radius)) + 1;
  const std::vector<int> xi = edgeIndexTable(width, margin, options.edge);
  const std::vector<int> yi = edgeIndexTable(rows, margin, options.edge);
  std::vector<float> plane(height.pixelCount());
  for (std::size_t i = 0; i < plane.size(); ++i) {
    plane[i] = height.data()[i * std::size_t(channels)] * depth;
  }

  Image occlusion(width, rows, 1, ColorSpace::Linear);
  occlusion.setSourceBitsPerChannel(16);
  const float strength = float(options.strength);
  parallelFor(
      rows,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          const float centre = plane[std::size_t(y) * std::size_t(width) + std::size_t(x)];
          float occluded = 0.0f;
          for (int d = 0; d < directions; ++d) {
            float steepest = 0.0f;  // tangent of the horizon; the surface's own plane at least
            const Tap* tap = &taps[std::size_t(d * steps)];
            for (int s = 0; s < steps; ++s, ++tap) {
              const int sx = xi[std::size_t(x + tap->dx + margin)];
              const int sy = yi[std::size_t(y + tap->dy + margin)];
              const float rise =
                  plane[std::size_t(sy) * std::size_t(width) + std::size_t(sx)] - centre;
              steepest = std::max(steepest, rise * tap->inverseDistance);
            }
            occluded += steepest / std::sqrt(1.0f + steepest * steepest);  // sin(atan(t))
          }
          occlusion.at(x, y, 0) =
              std::clamp(1.0f - strength * occluded / float(directions), 0.0f, 1.0f);
        }
      },
      control);
  return occlusion;
}

}  // namespace relief::core
