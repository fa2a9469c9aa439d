// FLIP, the perceptual difference of two images as a viewer flipping between them sees it
// (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild, "FLIP: A Difference
// Evaluator for Alternating Images", HPG 2020), the LDR version, written from the paper:
//
// - colour: both images in the opponent space YyCxCz are filtered by the contrast sensitivity
//   of the eye for each channel (sums of Gaussians, in degrees of visual angle), taken back to
//   linear RGB and clamped, then to L*a*b* with Hunt's adjustment (a*, b* scaled by L*/100);
//   the HyAB distance (|dL| + the Euclidean distance of a, b) raised to qc = 0.7 is mapped to
//   0..1: 0..pc of its maximum (pure green against pure blue) to 0..pt, the rest to pt..1
//   (pc = 0.4, pt = 0.95);
// - features: edges and points of the achromatic channel (first and second derivatives of a
//   Gaussian of 0.082 degrees peak to trough), the larger change in edge or point strength,
//   over sqrt(2), raised to qf = 0.5;
// - per pixel, colour error ^ (1 - feature error): a changed edge raises a small colour error.
//
// The FLIP value is the mean over pixels (0: identical, 1: as different as images get).
// Observer: 67 pixels per degree (0.7 m from a 0.7 m wide 3840-pixel monitor, the paper's).
#pragma once

#include "core/image/Image.h"

namespace relief::core::inline compression {

constexpr double kFlipDefaultPixelsPerDegree = 0.7 * 3840.0 / 0.7 * 3.14159265358979323846 / 180.0;

struct FlipResult {
  double mean = 0.0;
  double p95 = 0.0;  // the 95th percentile of the per-pixel error
  double maxError = 0.0;
  Image errorMap;  // one channel, the per-pixel error 0..1
  // The two pipelines' per-pixel errors (colour, redistributed to 0..1; feature, 0..1), kept
  // when asked for (tests, and the curious).
  Image colourError, featureError;
};

// `reference` and `test` must be the same size. Their first three channels are read as the
// image a viewer sees: sRGB-encoded colour as it is stored, linear data (height, roughness)
// shown as stored values; one channel is grey, two are red and green.
FlipResult measureFlip(const Image& reference, const Image& test,
                       double pixelsPerDegree = kFlipDefaultPixelsPerDegree,
                       bool keepComponents = false);

}  // namespace relief::core::inline compression
