// ImageFilters; see ImageFilters.h.
#include "core/generators/ImageFilters.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline generators {

std::vector<int> edgeIndexTable(int size, int margin, EdgeMode edge) {
  std::vector<int> table(std::size_t(size + 2 * margin));
  for (int i = -margin; i < size + margin; ++i) {
    table[std::size_t(i + margin)] = edgeIndex(i, size, edge);
  }
  return table;
}

Image gaussianBlur(const Image& image, double sigma, EdgeMode edge, const WorkControl& control) {
  if (!(sigma > 0.0))
    return image;
  const int radius = std::max(1, int(std::ceil(3.0 * sigma)));
  std::vector<float> weights(std::size_t(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const double w = std::exp(-0.5 * double(i * i) / (sigma * sigma));
    weights[std::size_t(i + radius)] = float(w);
    sum += w;
  }
  for (float& w : weights)
    w = float(w / sum);

  const int width = image.width(), height = image.height(), channels = image.channels();
  const std::vector<int> xIndex = edgeIndexTable(width, radius, edge);
  const std::vector<int> yIndex = edgeIndexTable(height, radius, edge);
  Image horizontal(width, height, channels, image.colorSpace());
  const WorkControl firstHalf{[&](double f) { control.report(0.5 * f); }, control.cancel};
  parallelFor(
      height,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          float* out = horizontal.pixel(x, y);
          for (int k = 0; k <= 2 * radius; ++k) {
            const float* in = image.pixel(xIndex[std::size_t(x + k)], y);
            for (int c = 0; c < channels; ++c)
              out[c] += weights[std::size_t(k)] * in[c];
          }
        }
      },
      firstHalf);
  Image result(width, height, channels, image.colorSpace());
  result.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  const WorkControl secondHalf{[&](double f) { control.report(0.5 + 0.5 * f); }, control.cancel};
  parallelFor(
      height,
      [&](int y) {
        float* out = result.pixel(0, y);
        for (int k = 0; k <= 2 * radius; ++k) {
          const float* in = horizontal.pixel(0, yIndex[std::size_t(y + k)]);
          const float w = weights[std::size_t(k)];
          for (int i = 0; i < width * channels; ++i)
            out[i] += w * in[i];
        }
      },
      secondHalf);
  return result;
}

Image luminance(const Image& image) {
  Image grey(image.width(), image.height(), 1, ColorSpace::Linear);
  const bool srgb = image.colorSpace() == ColorSpace::Srgb;
  const auto linear = [srgb](float v) { return srgb ? srgbToLinear(v) : v; };
  parallelFor(image.height(), [&](int y) {
    for (int x = 0; x < image.width(); ++x) {
      const float* p = image.pixel(x, y);
      grey.at(x, y, 0) = image.channels() >= 3 ? 0.2126f * linear(p[0]) + 0.7152f * linear(p[1]) +
                                                     0.0722f * linear(p[2])
                                               : linear(p[0]);
    }
  });
  return grey;
}

namespace {

// One output texel's taps along an axis: the first source index and the weights (normalised).
struct ResampleTaps {
  std::vector<int> first;
  std::vector<int> count;
  std::vector<float> weights;  // `count[i]` weights of output i, from offset[i]
  std::vector<std::size_t> offset;
};

double lanczos3(double x) {
  x = std::abs(x);
  if (x < 1e-8)
    return 1.0;
  if (x >= 3.0)
    return 0.0;
  const double pix = 3.14159265358979323846 * x;
  return 3.0 * std::sin(pix) * std::sin(pix / 3.0) / (pix * pix);
}

ResampleTaps resampleTaps(int sourceSize, int targetSize) {
  const double scale = double(sourceSize) / double(targetSize);
  const double support = 3.0 * std::max(1.0, scale);  // widened when shrinking
  const double step = 1.0 / std::max(1.0, scale);     // kernel units per source texel
  ResampleTaps taps;
  taps.first.resize(std::size_t(targetSize));
  taps.count.resize(std::size_t(targetSize));
  taps.offset.resize(std::size_t(targetSize));
  for (int i = 0; i < targetSize; ++i) {
    const double centre = (i + 0.5) * scale - 0.5;  // in source texel coordinates
    const int low = int(std::floor(centre - support)) + 1;
    const int high = int(std::ceil(centre + support)) - 1;
    taps.first[std::size_t(i)] = low;
    taps.count[std::size_t(i)] = high - low + 1;
    taps.offset[std::size_t(i)] = taps.weights.size();
    double sum = 0.0;
    for (int s = low; s <= high; ++s)
      sum += lanczos3((s - centre) * step);
    for (int s = low; s <= high; ++s)
      taps.weights.push_back(float(lanczos3((s - centre) * step) / sum));
  }
  return taps;
}

}  // namespace

Image resizeImage(const Image& image, int width, int height) {
  const int channels = image.channels();
  Image result(width, height, channels, image.colorSpace());
  result.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  if (image.isEmpty() || width <= 0 || height <= 0)
    return result;
  const ResampleTaps across = resampleTaps(image.width(), width);
  const ResampleTaps down = resampleTaps(image.height(), height);
  const auto clampTo = [](int i, int size) { return std::clamp(i, 0, size - 1); };
  // Rows first (source height x target width), then columns.
  Image wide(width, image.height(), channels, image.colorSpace());
  parallelFor(image.height(), [&](int y) {
    const float* source = image.pixel(0, y);
    float* target = wide.pixel(0, y);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(x);
      const float* weights = &across.weights[across.offset[i]];
      for (int c = 0; c < channels; ++c) {
        float sum = 0.0f;
        for (int k = 0; k < across.count[i]; ++k) {
          const int sx = clampTo(across.first[i] + k, image.width());
          sum += weights[k] * source[std::size_t(sx) * std::size_t(channels) + std::size_t(c)];
        }
        target[std::size_t(x) * std::size_t(channels) + std::size_t(c)] = sum;
      }
    }
  });
  const std::size_t rowValues = std::size_t(width) * std::size_t(channels);
  parallelFor(height, [&](int y) {
    const std::size_t i = std::size_t(y);
    const float* weights = &down.weights[down.offset[i]];
    float* target = result.pixel(0, y);
    std::fill(target, target + rowValues, 0.0f);
    for (int k = 0; k < down.count[i]; ++k) {
      const float* source = wide.pixel(0, clampTo(down.first[i] + k, image.height()));
      for (std::size_t v = 0; v < rowValues; ++v)
        target[v] += weights[k] * source[v];
    }
  });
  return result;
}

}  // namespace relief::core::inline generators
