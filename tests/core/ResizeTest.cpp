// resizeImage (core/generators/ImageFilters.h): a separable Lanczos-3 filter, widened when
// shrinking. Checked against what any normalised symmetric filter must do (keep a constant,
// keep a linear ramp where the taps are symmetric, average an alternating pattern away when
// halving) and against OpenImageIO's ImageBufAlgo::resize, which Relief used before, on
// photographs.
#include "core/generators/ImageFilters.h"
#include "support/TestPhotos.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include <cmath>

namespace relief::core {
namespace {

Image filled(int width, int height, int channels, float (*value)(int x, int y, int c)) {
  Image image(width, height, channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        image.pixel(x, y)[c] = value(x, y, c);
  return image;
}

TEST(Resize, AConstantStaysConstantShrinkingAndGrowing) {
  const Image flat = filled(37, 29, 3, [](int, int, int c) { return 0.25f + 0.25f * float(c); });
  for (const auto& [w, h] : {std::pair{11, 7}, {80, 64}, {37, 5}}) {
    const Image resized = resizeImage(flat, w, h);
    ASSERT_EQ(resized.width(), w);
    ASSERT_EQ(resized.height(), h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(resized.pixel(x, y)[c], 0.25f + 0.25f * float(c), 1e-5f) << x << "," << y;
  }
}

TEST(Resize, HalvingKeepsARampAndRemovesAnAlternation) {
  // Halving puts every output texel's centre between two source texels: the taps are
  // symmetric, so a linear ramp comes out as its value there (away from the clamped edges).
  const Image ramp = filled(64, 8, 1, [](int x, int, int) { return float(x) / 64.0f; });
  const Image half = resizeImage(ramp, 32, 4);
  for (int x = 4; x < 28; ++x)
    EXPECT_NEAR(half.pixel(x, 2)[0], (2.0f * float(x) + 0.5f) / 64.0f, 1e-4f) << x;
  // A one-texel alternation is above the halved image's Nyquist limit: the widened filter
  // leaves its mean, where point sampling would keep one phase (0 or 1).
  const Image stripes = filled(64, 8, 1, [](int x, int, int) { return float(x % 2); });
  const Image halved = resizeImage(stripes, 32, 4);
  for (int x = 4; x < 28; ++x)
    EXPECT_NEAR(halved.pixel(x, 2)[0], 0.5f, 0.02f) << x;
}

double psnr(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.valueCount(); ++i) {
    const double d = double(a.data()[i]) - double(b.data()[i]);
    sum += d * d;
  }
  return 10.0 * std::log10(double(a.valueCount()) / std::max(sum, 1e-30));
}

TEST(Resize, MatchesOpenImageIOsResizeOnPhotographs) {
  for (const Image& photo : test::photographCrops(256)) {
    for (const auto& [w, h] : {std::pair{128, 128}, {96, 160}}) {
      const Image ours = resizeImage(photo, w, h);
      const OIIO::ImageSpec sourceSpec(photo.width(), photo.height(), photo.channels(),
                                       OIIO::TypeDesc::FLOAT);
      const OIIO::ImageBuf source(sourceSpec, const_cast<float*>(photo.data()));
      Image theirs(w, h, photo.channels());
      OIIO::ImageBuf target(OIIO::ImageSpec(w, h, photo.channels(), OIIO::TypeDesc::FLOAT),
                            theirs.data());
      ASSERT_TRUE(OIIO::ImageBufAlgo::resize(target, source));
      EXPECT_GT(psnr(ours, theirs), 40.0) << w << "x" << h;
    }
  }
}

}  // namespace
}  // namespace relief::core
