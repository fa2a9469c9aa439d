// HeightFromNormal; see HeightFromNormal.h.
#include "core/generators/HeightFromNormal.h"

#include "core/base/ParallelFor.h"

#include <fftw3.h>

#include <QThread>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>

namespace relief::core::inline generators {
namespace {

// FFTW's planner is not thread-safe; execution of distinct plans is.
std::mutex& plannerMutex() {
  static std::mutex mutex;
  return mutex;
}

void initialiseFftwThreads() {
  static std::once_flag once;
  std::call_once(once, [] { fftwf_init_threads(); });
}

struct FftwDeleter {
  void operator()(void* p) const { fftwf_free(p); }
};
template <class T>
using FftwBuffer = std::unique_ptr<T[], FftwDeleter>;

template <class T>
FftwBuffer<T> allocate(std::size_t count) {
  return FftwBuffer<T>(static_cast<T*>(fftwf_malloc(sizeof(T) * count)));
}

// Slopes steeper than this (about 84 degrees) are clamped: a normal lying in the surface
// plane would make the gradient infinite.
constexpr float kMaxSlope = 10.0f;

// The padded area's gradients from the normals: in image coordinates (rows grow downward),
// dh/dx = -nx/nz and dh/drow = +ny/nz. The mirrored copies (Clamp edges) flip the sign of the
// derivative across the mirror.
void gradientsFromNormals(const Image& normals, float ySign, int paddedWidth, int paddedHeight,
                          float* gx, float* gy) {
  const int width = normals.width(), height = normals.height();
  const int channels = normals.channels();
  parallelFor(paddedHeight, [&](int y) {
    const bool flipY = y >= height;
    const int sourceY = flipY ? paddedHeight - 1 - y : y;
    for (int x = 0; x < paddedWidth; ++x) {
      const bool flipX = x >= width;
      const int sourceX = flipX ? paddedWidth - 1 - x : x;
      const float* p = normals.pixel(sourceX, sourceY);
      const float nx = 2.0f * p[0] - 1.0f;
      const float ny = (2.0f * p[std::min(1, channels - 1)] - 1.0f) * ySign;
      const float nz = std::max(channels >= 3 ? 2.0f * p[2] - 1.0f : 1.0f, 1.0f / kMaxSlope);
      const std::size_t i = std::size_t(y) * std::size_t(paddedWidth) + std::size_t(x);
      gx[i] = std::clamp(-nx / nz, -kMaxSlope, kMaxSlope) * (flipX ? -1.0f : 1.0f);
      gy[i] = std::clamp(ny / nz, -kMaxSlope, kMaxSlope) * (flipY ? -1.0f : 1.0f);
    }
  });
}

// Integrates the gradients' spectra in place: H = -i (wx Gx + wy Gy) / (wx^2 + wy^2), written
// into fx; the mean (DC term) is zero.
void integrateSpectrum(fftwf_complex* fx, const fftwf_complex* fy, int paddedWidth,
                       int paddedHeight) {
  const int spectrumWidth = paddedWidth / 2 + 1;
  const float twoPi = 2.0f * std::numbers::pi_v<float>;
  parallelFor(paddedHeight, [&](int ky) {
    const int frequencyY = ky <= paddedHeight / 2 ? ky : ky - paddedHeight;
    const float wy = twoPi * float(frequencyY) / float(paddedHeight);
    for (int kx = 0; kx < spectrumWidth; ++kx) {
      const float wx = twoPi * float(kx) / float(paddedWidth);
      const std::size_t i = std::size_t(ky) * std::size_t(spectrumWidth) + std::size_t(kx);
      const float denominator = wx * wx + wy * wy;
      if (denominator <= 0.0f) {
        fx[i][0] = fx[i][1] = 0.0f;
        continue;
      }
      const float re = wx * fx[i][0] + wy * fy[i][0];
      const float im = wx * fx[i][1] + wy * fy[i][1];
      // -i (re + i im) = im - i re
      fx[i][0] = im / denominator;
      fx[i][1] = -re / denominator;
    }
  });
}

// The top-left width x height of the inverse transform is the original area: normalised to
// [0, 1], with its range in texels.
HeightFromNormalResult normalisedHeight(const float* integrated, int paddedWidth, int paddedHeight,
                                        int width, int height) {
  const std::size_t realCount = std::size_t(paddedWidth) * std::size_t(paddedHeight);
  float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
  for (int y = 0; y < height; ++y) {
    const float* row = integrated + std::size_t(y) * std::size_t(paddedWidth);
    const auto [mn, mx] = std::minmax_element(row, row + width);
    low = std::min(low, *mn);
    high = std::max(high, *mx);
  }
  const float scale = 1.0f / float(realCount);  // FFTW's transforms are unnormalised
  HeightFromNormalResult result;
  result.rangeTexels = double(high - low) * scale;
  result.height = Image(width, height, 1, ColorSpace::Linear);
  result.height.setSourceBitsPerChannel(16);
  const float span = high > low ? high - low : 1.0f;
  parallelFor(height, [&](int y) {
    const float* row = integrated + std::size_t(y) * std::size_t(paddedWidth);
    for (int x = 0; x < width; ++x)
      result.height.at(x, y, 0) = (row[x] - low) / span;
  });
  return result;
}

}  // namespace

Result<HeightFromNormalResult> heightFromNormal(const Image& normals,
                                                const HeightFromNormalOptions& options,
                                                const WorkControl& control) {
  initialiseFftwThreads();
  const int width = normals.width(), height = normals.height();
  const bool mirror = options.edge == EdgeMode::Clamp;
  const int paddedWidth = mirror ? 2 * width : width;
  const int paddedHeight = mirror ? 2 * height : height;
  const std::size_t realCount = std::size_t(paddedWidth) * std::size_t(paddedHeight);
  const int spectrumWidth = paddedWidth / 2 + 1;
  const std::size_t complexCount = std::size_t(spectrumWidth) * std::size_t(paddedHeight);

  auto gx = allocate<float>(realCount);
  auto gy = allocate<float>(realCount);
  auto fx = allocate<fftwf_complex>(complexCount);
  auto fy = allocate<fftwf_complex>(complexCount);
  const float ySign = options.convention == NormalConvention::DirectX ? -1.0f : 1.0f;

  gradientsFromNormals(normals, ySign, paddedWidth, paddedHeight, gx.get(), gy.get());
  if (control.cancelled())
    return makeError("cancelled");
  control.report(0.15);

  fftwf_plan forwardX, forwardY, inverse;
  {
    const std::lock_guard<std::mutex> lock(plannerMutex());
    fftwf_plan_with_nthreads(std::max(1, QThread::idealThreadCount()));
    forwardX = fftwf_plan_dft_r2c_2d(paddedHeight, paddedWidth, gx.get(), fx.get(), FFTW_ESTIMATE);
    forwardY = fftwf_plan_dft_r2c_2d(paddedHeight, paddedWidth, gy.get(), fy.get(), FFTW_ESTIMATE);
    inverse = fftwf_plan_dft_c2r_2d(paddedHeight, paddedWidth, fx.get(), gx.get(), FFTW_ESTIMATE);
  }
  fftwf_execute(forwardX);
  control.report(0.35);
  fftwf_execute(forwardY);
  control.report(0.55);
  if (control.cancelled()) {
    const std::lock_guard<std::mutex> lock(plannerMutex());
    fftwf_destroy_plan(forwardX);
    fftwf_destroy_plan(forwardY);
    fftwf_destroy_plan(inverse);
    return makeError("cancelled");
  }

  integrateSpectrum(fx.get(), fy.get(), paddedWidth, paddedHeight);
  fftwf_execute(inverse);
  {
    const std::lock_guard<std::mutex> lock(plannerMutex());
    fftwf_destroy_plan(forwardX);
    fftwf_destroy_plan(forwardY);
    fftwf_destroy_plan(inverse);
  }
  control.report(0.85);

  HeightFromNormalResult result =
      normalisedHeight(gx.get(), paddedWidth, paddedHeight, width, height);
  control.report(1.0);
  return result;
}

}  // namespace relief::core::inline generators
