// Normal maps from height maps (reference 003, section 1.4, after NVIDIA's normal map filter):
// the tangent-space normal of the surface z = s * h(x, y) is normalize(-s dh/dx, -s dh/dy, 1),
// with the gradient in height units per texel and y pointing up the image. Gradients come from
// one of four kernels, optionally mixed over several blur levels (multi-scale detail).
#pragma once

#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/image/Image.h"

#include <array>

namespace relief::core::inline generators {

enum class GradientKernel {
  Central,  // (h[x+1] - h[x-1]) / 2: sharpest, most sensitive to noise
  Sobel,    // 3x3, smoothing (1 2 1) across the derivative
  Scharr,   // 3x3, smoothing (3 10 3): as cheap as Sobel, more rotation-invariant
  Sobel5,   // 5x5, derivative (1 2 0 -2 -1) and smoothing (1 4 6 4 1)
};

enum class NormalConvention {
  OpenGl,   // +Y up the image (Blender, Unity, Godot, glTF)
  DirectX,  // +Y down the image (Unreal, 3ds Max)
};

// The blur levels of multi-scale detail: level 0 is the height itself, levels 1-3 Gaussian
// blurs of these standard deviations in texels.
constexpr std::array<double, 4> kDetailSigmas = {0.0, 2.0, 4.0, 8.0};

struct NormalFromHeightOptions {
  GradientKernel kernel = GradientKernel::Sobel;
  // Slope per unit of height per texel: a rise of 1.0 over one texel tilts the normal as a
  // slope of `strength`. For a height map whose 1.0 spans heightScale UV units on a map W
  // texels wide, strength = heightScale * W reproduces the geometry exactly.
  float strength = 1.0f;
  NormalConvention convention = NormalConvention::OpenGl;
  EdgeMode edge = EdgeMode::Wrap;  // Wrap for tileable maps
  // Weights of the gradients of the detail levels; normalised by their sum. {1, 0, 0, 0} is a
  // plain single-scale filter.
  std::array<float, 4> detailWeights = {1.0f, 0.0f, 0.0f, 0.0f};
  // Multiplies the blur sigmas; a preview at half resolution uses 0.5.
  double texelScale = 1.0;
};

// From the first channel of `height`. Returns an RGB image encoding n * 0.5 + 0.5, linear,
// normalised. When `control` cancels, the texels not reached are left unset (the image is
// allocated for overwrite): discard a cancelled result, as runGenerator does.
Image normalMapFromHeight(const Image& height, const NormalFromHeightOptions& options,
                          const WorkControl& control = {});

// The gradient (dh/dx, dh/dy with y up, per texel) of `height` with one kernel, as a 2-channel
// image. Shared with the curvature generator.
Image heightGradient(const Image& height, GradientKernel kernel, EdgeMode edge,
                     const WorkControl& control = {});

}  // namespace relief::core::inline generators
