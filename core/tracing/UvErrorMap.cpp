// UvErrorMap; see UvErrorMap.h.
#include "core/tracing/UvErrorMap.h"

#include "core/base/ParallelFor.h"
#include "core/image/Heatmap.h"
#include "core/tracing/ReliefTracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

namespace relief::core::inline tracing {

namespace {

// ExactUvs' status channel.
constexpr float kStatusNotCovered = 0.0f;
constexpr float kStatusHit = 1.0f;
constexpr float kStatusMinified = 2.0f;
constexpr float kStatusMissed = 3.0f;

}  // namespace

Image traceExactUvs(const Image& coverage, const Image& eyeRays, const HeightField& field,
                    const std::function<void(int, int)>& progress,
                    const std::atomic<bool>* cancel) {
  const int width = coverage.width();
  const int height = coverage.height();
  Image exact(width, height, 4);
  std::atomic<int> done{0};
  WorkControl control;
  if (cancel)
    control.cancel = cancel;
  parallelFor(
      height,
      [&](int y) {
        for (int x = 0; x < width; ++x) {
          float* out = exact.pixel(x, y);
          out[2] = kStatusNotCovered;
          const float* uv = coverage.pixel(x, y);
          const float* ray = eyeRays.pixel(x, y);
          if ((cancel && cancel->load()) || uv[3] <= 0.0f)
            continue;
          if (uv[2] >= kErrorMaxMipLevel) {
            out[2] = kStatusMinified;
            continue;
          }
          const double vx = ray[2], vy = ray[3];
          const double vz = std::sqrt(std::max(0.0, 1.0 - vx * vx - vy * vy));
          const ViewRayHit hit = traceViewRay(field, {ray[0], ray[1]}, {vx, vy, vz});
          // Kept as the offset from the entry UV: small, so a float holds it exactly enough
          // (tiled UVs run to tens, where a float UV keeps a thousandth of a texel).
          out[0] = float(hit.uv.x - double(ray[0]));
          out[1] = float(hit.uv.y - double(ray[1]));
          out[2] = hit.hit ? kStatusHit : kStatusMissed;
        }
        const int finished = ++done;
        if (progress)
          progress(finished, height);
      },
      control);
  return exact;
}

UvErrorMap uvErrorAgainst(const Image& finalUv, const Image& eyeRays, const Image& exactUvs,
                          int fieldWidth, int fieldHeight) {
  UvErrorMap result;
  const int width = finalUv.width();
  const int height = finalUv.height();
  result.texels = Image(width, height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float& out = result.texels.at(x, y, 0);
      out = kErrorNotCovered;
      const float* uv = finalUv.pixel(x, y);
      const float* exact = exactUvs.pixel(x, y);
      const float* ray = eyeRays.pixel(x, y);
      if (uv[3] <= 0.0f || exact[2] == kStatusNotCovered || exact[2] == kStatusMissed)
        continue;
      if (exact[2] == kStatusMinified || uv[2] >= kErrorMaxMipLevel) {
        out = kErrorMinified;
        continue;
      }
      const double du = (double(uv[0]) - (double(ray[0]) + double(exact[0]))) * fieldWidth;
      const double dv = (double(uv[1]) - (double(ray[1]) + double(exact[1]))) * fieldHeight;
      out = float(std::hypot(du, dv));
    }
  }
  std::vector<float> covered;
  covered.reserve(result.texels.pixelCount());
  for (std::size_t i = 0; i < result.texels.valueCount(); ++i) {
    const float error = result.texels.data()[i];
    if (error >= 0.0f)
      covered.push_back(error);
    else if (error == kErrorMinified)
      ++result.minifiedPixels;
  }
  result.pixels = static_cast<long long>(covered.size());
  if (!covered.empty()) {
    result.mean = std::accumulate(covered.begin(), covered.end(), 0.0) / double(covered.size());
    result.maximum = *std::max_element(covered.begin(), covered.end());
    const auto rank = std::size_t(0.95 * double(covered.size() - 1));
    std::nth_element(covered.begin(), covered.begin() + std::ptrdiff_t(rank), covered.end());
    result.p95 = covered[rank];
  }
  return result;
}

UvErrorMap computeUvErrorMap(const Image& finalUv, const Image& eyeRays, const HeightField& field,
                             const std::function<void(int, int)>& progress,
                             const std::atomic<bool>* cancel) {
  return uvErrorAgainst(finalUv, eyeRays, traceExactUvs(finalUv, eyeRays, field, progress, cancel),
                        field.width(), field.height());
}

std::string describeUvError(const UvErrorMap& map) {
  char text[256];
  if (map.pixels == 0 && map.minifiedPixels > 0) {
    std::snprintf(text, sizeof text,
                  "every pixel (%lld) reads the height map minified (mip level %g or more), "
                  "where no technique can match the full-resolution trace: move closer",
                  map.minifiedPixels, double(kErrorMaxMipLevel));
    return text;
  }
  std::snprintf(text, sizeof text,
                "mean %.3f, 95th percentile %.3f, max %.2f texels over %lld pixels", map.mean,
                map.p95, map.maximum, map.pixels);
  std::string summary = text;
  if (map.minifiedPixels > 0) {
    std::snprintf(text, sizeof text,
                  "; %lld pixels where the height map is minified (mip level %g or more) left out",
                  map.minifiedPixels, double(kErrorMaxMipLevel));
    summary += text;
  }
  return summary;
}

Image colorizeErrorMap(const UvErrorMap& map, double maxTexels) {
  Image colors(map.texels.width(), map.texels.height(), 4, ColorSpace::Srgb);
  for (int y = 0; y < colors.height(); ++y) {
    for (int x = 0; x < colors.width(); ++x) {
      const float error = map.texels.at(x, y, 0);
      float* out = colors.pixel(x, y);
      if (error == kErrorNotCovered)
        continue;  // transparent
      const glm::vec3 color = error == kErrorMinified
                                  ? glm::vec3(kErrorMinifiedGrey)
                                  : heatmapColor(float(error / std::max(maxTexels, 1e-9)));
      out[0] = color.r;
      out[1] = color.g;
      out[2] = color.b;
      out[3] = 1.0f;
    }
  }
  return colors;
}

}  // namespace relief::core::inline tracing
