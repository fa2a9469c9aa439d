// ImageCompare; see ImageCompare.h.
#include "ImageCompare.h"

#include "TestPaths.h"
#include "core/compression/CompressionMetrics.h"
#include "core/image/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace relief::test {

double decodedPsnr(const core::Image& map, const core::CompressedTexture& texture) {
  return core::measureImageError(map, core::decodeAsMap(texture).value()).psnr;
}

ImageDifference compareImages(const core::Image& a, const core::Image& b) {
  ImageDifference difference;
  if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels()) {
    difference.sameShape = false;
    difference.maxError = difference.meanError = 1.0;
    return difference;
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < a.valueCount(); ++i) {
    const double error = std::abs(double(a.data()[i]) - double(b.data()[i]));
    difference.maxError = std::max(difference.maxError, error);
    sum += error;
  }
  difference.meanError = a.valueCount() ? sum / double(a.valueCount()) : 0.0;
  return difference;
}

::testing::AssertionResult matchesBaseline(const core::Image& actual, const std::string& name,
                                           double maxTolerance, double meanTolerance) {
  const std::string baselinePath = sourcePath("tests/baselines/" + name + ".png");
  const char* update = std::getenv("RELIEF_UPDATE_BASELINES");
  if (update && std::string(update) == "1") {
    if (core::Status saved = core::saveImage(actual, baselinePath, core::SampleFormat::UInt8);
        !saved) {
      return ::testing::AssertionFailure() << saved.error();
    }
    return ::testing::AssertionSuccess() << "baseline written: " << baselinePath;
  }
  core::Result<core::Image> baseline = core::loadImage(baselinePath);
  if (!baseline) {
    return ::testing::AssertionFailure()
           << baseline.error() << " (run with RELIEF_UPDATE_BASELINES=1 to create it)";
  }
  core::Image expected = std::move(baseline).value();
  expected.setColorSpace(actual.colorSpace());
  const ImageDifference difference = compareImages(actual, expected);
  if (difference.sameShape && difference.maxError <= maxTolerance &&
      difference.meanError <= meanTolerance) {
    return ::testing::AssertionSuccess();
  }
  const std::string folder = failureOutputFolder();
  const std::string actualPath = folder + "/" + name + "-actual.png";
  const std::string diffPath = folder + "/" + name + "-diff.png";
  (void)core::saveImage(actual, actualPath, core::SampleFormat::UInt8);
  if (difference.sameShape) {
    core::Image diff(actual.width(), actual.height(), actual.channels(), core::ColorSpace::Linear);
    for (std::size_t i = 0; i < diff.valueCount(); ++i) {
      diff.data()[i] = std::min(1.0f, 8.0f * std::abs(actual.data()[i] - expected.data()[i]));
    }
    for (int y = 0; y < diff.height() && diff.channels() == 4; ++y) {
      for (int x = 0; x < diff.width(); ++x)
        diff.at(x, y, 3) = 1.0f;
    }
    (void)core::saveImage(diff, diffPath, core::SampleFormat::UInt8);
  }
  return ::testing::AssertionFailure()
         << name << ": " << (difference.sameShape ? "" : "size differs; ") << "max error "
         << difference.maxError * 255.0 << "/255 (tolerance " << maxTolerance * 255.0 << "), mean "
         << difference.meanError * 255.0 << "/255 (tolerance " << meanTolerance * 255.0
         << "); wrote " << actualPath << " and " << diffPath;
}

std::vector<float> readFloat32File(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    return {};
  std::vector<float> values(std::size_t(in.tellg()) / sizeof(float));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  return values;
}

double worstDifference(const core::Image& image, const std::vector<float>& expected) {
  if (expected.size() !=
      std::size_t(image.width()) * std::size_t(image.height()) * std::size_t(image.channels())) {
    return INFINITY;
  }
  double worst = 0.0;
  std::size_t i = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      for (int c = 0; c < image.channels(); ++c)
        worst = std::max(worst, double(std::abs(expected[i++] - image.at(x, y, c))));
    }
  }
  return worst;
}

}  // namespace relief::test
