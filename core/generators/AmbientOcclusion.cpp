// AmbientOcclusion; see AmbientOcclusion.h.
#include "core/generators/AmbientOcclusion.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace relief::core::inline generators {

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
  // Away from the borders every tap is a fixed offset in the plane: one add and one load, no
  // edge lookups (most texels of a large map).
  std::vector<std::ptrdiff_t> offsets(taps.size());
  for (std::size_t t = 0; t < taps.size(); ++t) {
    offsets[t] = std::ptrdiff_t(taps[t].dy) * width + taps[t].dx;
  }
  const int reach = int(std::ceil(radius)) + 1;
  const auto occlusionAt = [&](int x, int y, bool interior) {
    const std::size_t index = std::size_t(y) * std::size_t(width) + std::size_t(x);
    const float centre = plane[index];
    float occluded = 0.0f;
    for (int d = 0; d < directions; ++d) {
      float steepest = 0.0f;  // tangent of the horizon; the surface's own plane at least
      const std::size_t first = std::size_t(d * steps);
      for (std::size_t t = first; t < first + std::size_t(steps); ++t) {
        const float sample =
            interior
                ? plane[std::size_t(std::ptrdiff_t(index) + offsets[t])]
                : plane[std::size_t(yi[std::size_t(y + taps[t].dy + margin)]) * std::size_t(width) +
                        std::size_t(xi[std::size_t(x + taps[t].dx + margin)])];
        steepest = std::max(steepest, (sample - centre) * taps[t].inverseDistance);
      }
      occluded += steepest / std::sqrt(1.0f + steepest * steepest);  // sin(atan(t))
    }
    return std::clamp(1.0f - strength * occluded / float(directions), 0.0f, 1.0f);
  };
  parallelFor(
      rows,
      [&](int y) {
        const bool interiorRow = y >= reach && y < rows - reach;
        for (int x = 0; x < width; ++x) {
          const bool interior = interiorRow && x >= reach && x < width - reach;
          occlusion.at(x, y, 0) = occlusionAt(x, y, interior);
        }
      },
      control);
  return occlusion;
}

}  // namespace relief::core::inline generators
