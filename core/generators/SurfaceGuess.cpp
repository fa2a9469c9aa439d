// Roughness and metallic guesses; see SurfaceGuess.h.
#include "core/generators/SurfaceGuess.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace relief::core::inline generators {
namespace {

// Linear luminance and HSV saturation (of the stored values) of a texel.
struct Tone {
  float luminance = 0.0f;
  float saturation = 0.0f;
};

Tone toneAt(const Image& color, int x, int y) {
  const float* texel = color.pixel(x, y);
  if (color.channels() < 3) {
    const float value = color.colorSpace() == ColorSpace::Srgb ? srgbToLinear(texel[0]) : texel[0];
    return {value, 0.0f};
  }
  const bool srgb = color.colorSpace() == ColorSpace::Srgb;
  std::array<float, 3> linear{};
  for (int c = 0; c < 3; ++c)
    linear[std::size_t(c)] = srgb ? srgbToLinear(texel[c]) : texel[c];
  const float high = std::max({texel[0], texel[1], texel[2]});
  const float low = std::min({texel[0], texel[1], texel[2]});
  return {0.2126f * linear[0] + 0.7152f * linear[1] + 0.0722f * linear[2],
          high > 1e-6f ? (high - low) / high : 0.0f};
}

// The luminance below which `fraction` of the texels lie (a 4096-bin histogram of 0..1).
float luminancePercentile(const std::vector<float>& luminance, double fraction) {
  constexpr int kBins = 4096;
  std::vector<std::size_t> counts(kBins, 0);
  for (float value : luminance)
    ++counts[std::size_t(std::clamp(int(value * kBins), 0, kBins - 1))];
  const double target = fraction * double(luminance.size());
  double seen = 0.0;
  for (int bin = 0; bin < kBins; ++bin) {
    seen += double(counts[std::size_t(bin)]);
    if (seen >= target)
      return (float(bin) + 0.5f) / float(kBins);
  }
  return 1.0f;
}

// 0 below `low - softness`, 1 above `low + softness`, and the same falling around `high`; a
// range reaching 0 or 1 has no edge there (white is not "above" a range that ends at 1).
float softRange(float value, double low, double high, double softness) {
  const auto step = [&](double edge, double x) {
    if (softness <= 0.0)
      return x >= edge ? 1.0 : 0.0;
    const double t = std::clamp((x - edge + softness) / (2.0 * softness), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
  };
  const double above = low <= 0.0 ? 1.0 : step(low, value);
  const double below = high >= 1.0 ? 1.0 : 1.0 - step(high, value);
  return float(above * below);
}

void summarise(SurfaceGuess& guess) {
  const Image& map = guess.map;
  double low = 1.0, high = 0.0, sum = 0.0, metal = 0.0;
  for (std::size_t i = 0; i < map.pixelCount(); ++i) {
    const double value = map.data()[i];
    low = std::min(low, value);
    high = std::max(high, value);
    sum += value;
    metal += value > 0.5 ? 1.0 : 0.0;
  }
  const double count = double(std::max<std::size_t>(map.pixelCount(), 1));
  guess.low = low;
  guess.high = high;
  guess.mean = sum / count;
  guess.metalFraction = metal / count;
}

}  // namespace

SurfaceGuess guessRoughness(const Image& color, const Image* height,
                            const RoughnessGuessOptions& options, const WorkControl& control) {
  const int width = color.width(), rows = color.height();
  std::vector<float> luminance(color.pixelCount());
  std::vector<float> saturation(color.pixelCount());
  parallelFor(rows, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Tone tone = toneAt(color, x, y);
      luminance[std::size_t(y) * std::size_t(width) + std::size_t(x)] = tone.luminance;
      saturation[std::size_t(y) * std::size_t(width) + std::size_t(x)] = tone.saturation;
    }
  });
  const float dark = luminancePercentile(luminance, 0.05);
  const float bright = std::max(luminancePercentile(luminance, 0.95), dark + 1e-3f);

  // The cavity term: the blurred height's Laplacian (positive in a pit) over twice its RMS,
  // clamped to -1..1, so `cavity` means the same on a shallow and a deep height map.
  std::vector<float> concavity;
  if (height && options.cavity > 0.0) {
    const Image smooth =
        gaussianBlur(*height, options.cavityRadius * options.texelScale, options.edge, control);
    concavity.resize(color.pixelCount());
    const auto at = [&](int x, int y) {
      return smooth.at(edgeIndex(x, width, options.edge), edgeIndex(y, rows, options.edge), 0);
    };
    parallelFor(rows, [&](int y) {
      for (int x = 0; x < width; ++x)
        concavity[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
            at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1) - 4.0f * at(x, y);
    });
    double squares = 0.0;
    for (float value : concavity)
      squares += double(value) * value;
    const float scale =
        float(1.0 / std::max(2.0 * std::sqrt(squares / double(concavity.size())), 1e-12));
    for (float& value : concavity)
      value = std::clamp(value * scale, -1.0f, 1.0f);
  }

  SurfaceGuess guess;
  guess.map = Image::forOverwrite(width, rows, 1);
  guess.map.setSourceBitsPerChannel(16);
  parallelFor(
      rows,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
          const double t = std::clamp((luminance[i] - dark) / (bright - dark), 0.0f, 1.0f);
          double roughness = options.roughest + (options.smoothest - options.roughest) * t;
          roughness -= options.saturation * saturation[i] * 0.5;
          if (!concavity.empty())
            roughness += options.cavity * 0.5 * concavity[i];
          guess.map.at(x, y, 0) = float(std::clamp(roughness, 0.0, 1.0));
        }
      },
      control);
  summarise(guess);
  return guess;
}

SurfaceGuess guessMetallic(const Image& color, const MetallicGuessOptions& options,
                           const WorkControl& control) {
  SurfaceGuess guess;
  guess.map = Image::forOverwrite(color.width(), color.height(), 1);
  guess.map.setSourceBitsPerChannel(8);
  parallelFor(
      color.height(),
      [&](int y) {
        for (int x = 0; x < color.width(); ++x) {
          const Tone tone = toneAt(color, x, y);
          guess.map.at(x, y, 0) = softRange(tone.luminance, options.brightnessLow,
                                            options.brightnessHigh, options.softness) *
                                  softRange(tone.saturation, options.saturationLow,
                                            options.saturationHigh, options.softness);
        }
      },
      control);
  summarise(guess);
  return guess;
}

}  // namespace relief::core::inline generators
