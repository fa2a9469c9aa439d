// CompressionMetrics; see CompressionMetrics.h.
#include "core/compression/CompressionMetrics.h"

#include "core/image/PlaneConvolution.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace relief::core::inline compression {
namespace {

double psnrOf(double mse) {
  return mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
}

double percentile(std::vector<float> values, double fraction) {
  if (values.empty())
    return 0.0;
  const std::size_t k = std::min(values.size() - 1, std::size_t(fraction * double(values.size())));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

// Separable 11-tap Gaussian (sigma 1.5), edges clamped.
std::vector<float> gaussianBlur(const std::vector<float>& plane, int width, int height) {
  constexpr int kRadius = 5;
  std::vector<float> kernel(2 * kRadius + 1);
  float sum = 0.0f;
  for (int i = -kRadius; i <= kRadius; ++i) {
    kernel[std::size_t(i + kRadius)] = std::exp(-float(i * i) / (2.0f * 1.5f * 1.5f));
    sum += kernel[std::size_t(i + kRadius)];
  }
  for (float& k : kernel)
    k /= sum;
  std::vector<float> rows(plane.size()), out(plane.size());
  convolvePlane(plane.data(), rows.data(), width, height, kernel, true);
  convolvePlane(rows.data(), out.data(), width, height, kernel, false);
  return out;
}

// SSIM of one channel (Wang, Bovik, Sheikh, Simoncelli 2004), C1 = (0.01 L)^2,
// C2 = (0.03 L)^2 with L = 1.
double channelSsim(const Image& a, const Image& b, int channel) {
  const int width = a.width(), height = a.height();
  const std::size_t n = a.pixelCount();
  std::vector<float> x(n), y(n), xx(n), yy(n), xy(n);
  for (std::size_t p = 0; p < n; ++p) {
    x[p] = a.data()[p * std::size_t(a.channels()) + std::size_t(channel)];
    y[p] = b.data()[p * std::size_t(b.channels()) + std::size_t(channel)];
    xx[p] = x[p] * x[p];
    yy[p] = y[p] * y[p];
    xy[p] = x[p] * y[p];
  }
  const std::vector<float> mx = gaussianBlur(x, width, height), my = gaussianBlur(y, width, height),
                           sxx = gaussianBlur(xx, width, height),
                           syy = gaussianBlur(yy, width, height),
                           sxy = gaussianBlur(xy, width, height);
  constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double total = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    const double muX = mx[p], muY = my[p];
    const double varX = sxx[p] - muX * muX, varY = syy[p] - muY * muY, cov = sxy[p] - muX * muY;
    total += ((2.0 * muX * muY + c1) * (2.0 * cov + c2)) /
             ((muX * muX + muY * muY + c1) * (varX + varY + c2));
  }
  return total / double(n);
}

}  // namespace

HdrError measureHdrError(const Image& reference, const Image& candidate) {
  HdrError result;
  if (reference.width() != candidate.width() || reference.height() != candidate.height() ||
      reference.isEmpty())
    return result;
  const auto rgb = [](const Image& image, std::size_t p, int c) {
    const float value = image.data()[p * std::size_t(image.channels()) +
                                     std::size_t(std::min(c, image.channels() - 1))];
    return std::isfinite(value) ? double(value) : 0.0;
  };
  const std::size_t pixels = reference.pixelCount();
  double logLuminance = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 3; ++c)
      result.referenceIsHdr =
          result.referenceIsHdr || rgb(reference, p, c) > 1.0 || rgb(reference, p, c) < 0.0;
    const double luminance = 0.2126 * rgb(reference, p, 0) + 0.7152 * rgb(reference, p, 1) +
                             0.0722 * rgb(reference, p, 2);
    logLuminance += std::log2(std::max(luminance, 1.0 / 16384.0));
  }
  const double key = logLuminance / double(pixels);
  const int middle = int(std::lround(std::log2(0.18) - key));
  result.firstStop = middle - 3;
  result.lastStop = middle + 3;
  // (v 2^c)^(1/2.2) = v^(1/2.2) 2^(c/2.2): one power per value, a factor per stop.
  double gains[7];
  for (int stop = result.firstStop; stop <= result.lastStop; ++stop)
    gains[stop - result.firstStop] = std::exp2(double(stop) / 2.2);
  const auto display = [](double gammaValue, double gain) {
    return std::round(std::min(gammaValue * gain, 1.0) * 255.0);
  };
  double squared = 0.0, logError = 0.0;
  const double epsilon = 1.0 / 16384.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 3; ++c) {
      const double a = rgb(reference, p, c), b = rgb(candidate, p, c);
      logError += std::abs(std::log2((std::abs(a) + epsilon) / (std::abs(b) + epsilon)));
      const double ga = std::pow(std::max(0.0, a), 1.0 / 2.2);
      const double gb = std::pow(std::max(0.0, b), 1.0 / 2.2);
      for (const double gain : gains) {
        const double d = display(ga, gain) - display(gb, gain);
        squared += d * d;
      }
    }
  }
  const double stops = double(result.lastStop - result.firstStop + 1);
  const double mse = squared / (double(pixels) * 3.0 * stops);
  result.exposurePsnr =
      mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  result.meanLog2Error = logError / (double(pixels) * 3.0);
  return result;
}

ImageError measureImageError(const Image& reference, const Image& candidate) {
  ImageError result;
  const int channels = std::min(reference.channels(), candidate.channels());
  if (reference.width() != candidate.width() || reference.height() != candidate.height() ||
      channels == 0) {
    return result;
  }
  const std::size_t n = reference.pixelCount();
  result.channels.resize(std::size_t(channels));
  double ssimSum = 0.0;
  for (int c = 0; c < channels; ++c) {
    ChannelError& error = result.channels[std::size_t(c)];
    double sum = 0.0;
    for (std::size_t p = 0; p < n; ++p) {
      const double d = double(reference.data()[p * std::size_t(reference.channels()) + c]) -
                       double(candidate.data()[p * std::size_t(candidate.channels()) + c]);
      sum += d * d;
      error.maxError = std::max(error.maxError, std::abs(d));
    }
    error.mse = sum / double(n);
    error.psnr = psnrOf(error.mse);
    result.mse += error.mse / channels;
    result.maxError = std::max(result.maxError, error.maxError);
    ssimSum += channelSsim(reference, candidate, c);
  }
  result.psnr = psnrOf(result.mse);
  result.ssim = ssimSum / channels;
  return result;
}

NormalError measureNormalError(const Image& reference, const Image& candidate) {
  NormalError result;
  if (reference.width() != candidate.width() || reference.height() != candidate.height() ||
      reference.channels() < 3 || candidate.channels() < 3) {
    return result;
  }
  const std::size_t n = reference.pixelCount();
  std::vector<float> angles(n);
  const auto unit = [](const float* stored, double v[3]) {
    double length = 0.0;
    for (int c = 0; c < 3; ++c) {
      v[c] = stored[c] * 2.0 - 1.0;
      length += v[c] * v[c];
    }
    length = std::sqrt(length);
    for (int c = 0; c < 3; ++c)
      v[c] = length > 1e-12 ? v[c] / length : (c == 2 ? 1.0 : 0.0);
  };
  double sum = 0.0;
  std::size_t above = 0;
  for (std::size_t p = 0; p < n; ++p) {
    double a[3], b[3];
    unit(reference.data() + p * std::size_t(reference.channels()), a);
    unit(candidate.data() + p * std::size_t(candidate.channels()), b);
    const double cosine = std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], -1.0, 1.0);
    const double degrees = std::acos(cosine) * 180.0 / std::numbers::pi;
    angles[p] = float(degrees);
    sum += degrees;
    result.maxDegrees = std::max(result.maxDegrees, degrees);
    above += degrees > 2.0 ? 1 : 0;
  }
  result.meanDegrees = sum / double(n);
  result.shareAbove2Degrees = double(above) / double(n);
  result.p99Degrees = percentile(std::move(angles), 0.99);
  return result;
}

HeightError measureHeightError(const Image& reference, const Image& candidate, double heightScale) {
  HeightError result;
  if (reference.width() != candidate.width() || reference.height() != candidate.height())
    return result;
  const std::size_t n = reference.pixelCount();
  const double texelsPerUnit = heightScale * reference.width();
  std::vector<float> shifts(n);
  double sum = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    const double shift = std::abs(double(reference.data()[p * std::size_t(reference.channels())]) -
                                  double(candidate.data()[p * std::size_t(candidate.channels())])) *
                         texelsPerUnit;
    shifts[p] = float(shift);
    sum += shift;
    result.maxTexels = std::max(result.maxTexels, shift);
  }
  result.meanTexels = sum / double(n);
  result.p99Texels = percentile(std::move(shifts), 0.99);
  return result;
}

SizeFigures measureSize(TextureFormat format, int sourceChannels, std::uint64_t bytesWithMips) {
  SizeFigures figures;
  figures.bytes = bytesWithMips;
  figures.bitsPerPixel = bitsPerPixel(format);
  figures.ratioToRgba8 = 32.0 / figures.bitsPerPixel;
  figures.ratioToSource = 8.0 * std::clamp(sourceChannels, 1, 4) / figures.bitsPerPixel;
  return figures;
}

}  // namespace relief::core::inline compression
