// Image comparison for render tests: max and mean absolute error per channel value, and a
// baseline check that writes the actual and a difference image when it fails.
#pragma once

#include "core/compression/Compressor.h"
#include "core/image/Image.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace relief::test {

struct ImageDifference {
  double maxError = 0.0;   // largest |a - b| over all channel values, 0..1
  double meanError = 0.0;  // mean |a - b| over all channel values
  bool sameShape = true;
};

ImageDifference compareImages(const core::Image& a, const core::Image& b);

// PSNR of `texture`'s level 0, decoded as a map, against `map`.
double decodedPsnr(const core::Image& map, const core::CompressedTexture& texture);

// Reference texels as the conformance scripts write them: a file of float32 values, row by row,
// channels interleaved (empty when the file cannot be read).
std::vector<float> readFloat32File(const std::string& path);
// The largest |difference| between an image and such texels, or infinity when the counts differ.
double worstDifference(const core::Image& image, const std::vector<float>& expected);

// Compares with tests/baselines/<name>.png. Set RELIEF_UPDATE_BASELINES=1 to (re)write the
// baseline instead. On failure writes <name>-actual.png and <name>-diff.png (difference x8)
// into failureOutputFolder().
::testing::AssertionResult matchesBaseline(const core::Image& actual, const std::string& name,
                                           double maxTolerance, double meanTolerance);

}  // namespace relief::test
