// RoughnessFold; see RoughnessFold.h.
#include "core/compression/RoughnessFold.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline compression {

double foldedRoughness(double roughness, double meanNormalLength) {
  const double r = std::clamp(meanNormalLength, 0.0, 1.0);
  const double alpha = roughness * roughness;
  if (r >= 1.0 - 1e-7)
    return std::min(roughness, 1.0);
  const double kappa = (3.0 * r - r * r * r) / (1.0 - r * r);
  // No concentration at all (r = 0: normals cancel out) is as rough as GGX goes.
  if (kappa <= 1e-9)
    return 1.0;
  const double widened = alpha * alpha + 2.0 / kappa;
  return std::min(1.0, std::sqrt(std::sqrt(widened)));
}

std::vector<Image> meanNormalLengths(const Image& normals) {
  // Level 0's unit vectors, then plain area averages of them (the data path of MipChain: no
  // renormalising), so each level's texel is the mean over its whole footprint.
  Image vectors = Image::forOverwrite(normals.width(), normals.height(), 3);
  parallelFor(normals.height(), [&](int y) {
    for (int x = 0; x < normals.width(); ++x) {
      const float* in = normals.pixel(x, y);
      float n[3] = {in[0] * 2.0f - 1.0f, normals.channels() > 1 ? in[1] * 2.0f - 1.0f : 0.0f,
                    normals.channels() > 2 ? in[2] * 2.0f - 1.0f : 1.0f};
      const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      float* out = vectors.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        out[c] = length > 1e-8f ? n[c] / length : (c == 2 ? 1.0f : 0.0f);
    }
  });
  std::vector<Image> lengths;
  while (vectors.width() > 1 || vectors.height() > 1) {
    vectors = downsampleForSlot(vectors, MapSlot::Height, MipFilter::Box);
    Image level(vectors.width(), vectors.height(), 1);
    for (int y = 0; y < vectors.height(); ++y) {
      for (int x = 0; x < vectors.width(); ++x) {
        const float* v = vectors.pixel(x, y);
        level.at(x, y, 0) = std::min(1.0f, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
      }
    }
    lengths.push_back(std::move(level));
  }
  return lengths;
}

std::vector<Image> foldedRoughnessLevels(const Image& roughness, const Image& normals,
                                         MipFilter filter) {
  const std::vector<Image> lengths = meanNormalLengths(normals);
  std::vector<Image> levels;
  Image plain = roughness;
  for (const Image& length : lengths) {
    plain = downsampleForSlot(plain, MapSlot::Roughness, filter);
    Image folded(plain.width(), plain.height(), 1);
    folded.setSourceBitsPerChannel(roughness.sourceBitsPerChannel());
    for (int y = 0; y < plain.height(); ++y) {
      for (int x = 0; x < plain.width(); ++x)
        folded.at(x, y, 0) = float(foldedRoughness(plain.at(x, y, 0), length.at(x, y, 0)));
    }
    levels.push_back(std::move(folded));
  }
  return levels;
}

}  // namespace relief::core::inline compression
