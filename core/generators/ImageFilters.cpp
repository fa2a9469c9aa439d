// ImageFilters; see ImageFilters.h.
#include "core/generators/ImageFilters.h"

#include "core/base/ParallelFor.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

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

Image resizeImage(const Image& image, int width, int height) {
  const OIIO::ImageSpec sourceSpec(image.width(), image.height(), image.channels(),
                                   OIIO::TypeDesc::FLOAT);
  // Wraps our pixels without copying them.
  const OIIO::ImageBuf source(sourceSpec, const_cast<float*>(image.data()));
  OIIO::ImageSpec targetSpec(width, height, image.channels(), OIIO::TypeDesc::FLOAT);
  Image result(width, height, image.channels(), image.colorSpace());
  result.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  OIIO::ImageBuf target(targetSpec, result.data());
  OIIO::ImageBufAlgo::resize(target, source);
  return result;
}

}  // namespace relief::core::inline generators
