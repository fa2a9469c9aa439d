// The `error` view's numbers: for every pixel of a frame, how far (in texels) the renderer's
// final UV is from the exact intersection found by the reference tracer.
//
// The tracer intersects the full-resolution map. Where the viewport reads the height map at mip
// level 1 or coarser, every technique sees a filtered map (the marches a trilinear blend, the
// exact tracers a pyramid block, then that blend), so the comparison measures the mip chain, not
// the technique: a plane seen from afar read 3.2 texels of mean error for POM and 3.6 for the
// quadtree, which is exact. Those pixels are marked and left out of the statistics.
#pragma once

#include "core/image/Image.h"
#include "core/tracing/HeightField.h"

#include <atomic>
#include <functional>
#include <string>

namespace relief::core::inline tracing {

// Values of UvErrorMap::texels that are not errors.
inline constexpr float kErrorNotCovered = -1.0f;  // the mesh is not drawn there
inline constexpr float kErrorMinified = -2.0f;    // the map is read at kErrorMaxMipLevel or coarser

// The mip level from which a pixel is not compared.
inline constexpr float kErrorMaxMipLevel = 1.0f;

struct UvErrorMap {
  Image texels;       // 1 channel: error in texels, or one of the markers above
  double mean = 0.0;  // over compared pixels
  double p95 = 0.0;
  double maximum = 0.0;
  long long pixels = 0;          // compared pixels
  long long minifiedPixels = 0;  // covered but read at kErrorMaxMipLevel or coarser
};

// `finalUv`: a float render of the uv view (rg = final texture UV, b = the height map's mip
// level there, a > 0 where covered).
// `eyeRays`: a float render of the eye rays (rg = entry texture UV, ba = view direction xy in
// tangent space, z = sqrt(1 - x^2 - y^2)). Runs on all cores; `progress(done, total)` is
// called from worker threads now and then; `cancel` stops early (the result is then partial).
UvErrorMap computeUvErrorMap(const Image& finalUv, const Image& eyeRays, const HeightField& field,
                             const std::function<void(int done, int total)>& progress = {},
                             const std::atomic<bool>* cancel = nullptr);

// The same in two parts, for many frames of one view (the cost table: one exact trace, a frame
// per technique). traceExactUvs traces the eye rays where `coverage` (a frame's float uv view)
// is covered and not minified: rg the exact UV less the entry UV, b a status (not covered,
// hit, minified, missed). uvErrorAgainst compares a frame's UVs with it, the same eye rays
// giving the entry UVs back.
Image traceExactUvs(const Image& coverage, const Image& eyeRays, const HeightField& field,
                    const std::function<void(int done, int total)>& progress = {},
                    const std::atomic<bool>* cancel = nullptr);
UvErrorMap uvErrorAgainst(const Image& finalUv, const Image& eyeRays, const Image& exactUvs,
                          int fieldWidth, int fieldHeight);

// "mean M, 95th percentile P, max X texels over N pixels", and how many minified pixels were left
// out: the summary the CLI prints and the viewport shows.
std::string describeUvError(const UvErrorMap& map);

// The error as heat-map colours (sRGB RGBA, alpha 0 where not covered), 0..maxTexels; minified
// pixels in kErrorMinifiedGrey.
Image colorizeErrorMap(const UvErrorMap& map, double maxTexels);

// The error the heat map's top colour stands for in the viewport, the CLI and their legends: a
// quarter texel, where parallax errors start to show as swimming.
inline constexpr double kErrorDisplayTexels = 0.25;

// The grey (sRGB, 0..1) of pixels left out for being minified; the legends name it.
inline constexpr float kErrorMinifiedGrey = 0.35f;

}  // namespace relief::core::inline tracing
