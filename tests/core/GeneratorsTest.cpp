// The map generators against analytic answers: normals of a tilted plane and of a product of
// sines (each kernel's result predicted exactly by its frequency response), the conventions,
// tileable and clamped edges, height -> normal -> height round trips, AO, curvature, packing
// and bad input.
#include "core/generators/Generators.h"
#include "core/generators/NormalFromHeight.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <cmath>
#include <numbers>

namespace relief::core {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 decoded(const Image& normals, int x, int y) {
  const float* p = normals.pixel(x, y);
  return glm::normalize(glm::dvec3(p[0], p[1], p[2]) * 2.0 - 1.0);
}

double angleDeg(glm::dvec3 a, glm::dvec3 b) {
  return glm::degrees(
      std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

Image field(int width, int height, double (*h)(int x, int row, int width, int height)) {
  Image image(width, height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      image.at(x, y, 0) = float(h(x, y, width, height));
  }
  return image;
}

NormalFromHeightOptions normalOptions(GradientKernel kernel, float strength, EdgeMode edge) {
  NormalFromHeightOptions options;
  options.kernel = kernel;
  options.strength = strength;
  options.edge = edge;
  return options;
}

constexpr GradientKernel kKernels[] = {GradientKernel::Central, GradientKernel::Sobel,
                                       GradientKernel::Scharr, GradientKernel::Sobel5};

TEST(NormalFromHeight, EveryKernelIsExactOnATiltedPlane) {
  // h rises by a per texel to the right and b per texel up the image (rows go down): every
  // kernel is exact for a linear function.
  const float a = 0.01f, b = 0.004f, strength = 20.0f;
  Image height(32, 32, 1);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x)
      height.at(x, y, 0) = 0.5f + a * float(x) - b * float(y);
  }
  const glm::dvec3 expected = glm::normalize(glm::dvec3(-strength * a, -strength * b, 1.0));
  for (GradientKernel kernel : kKernels) {
    const Image normals =
        normalMapFromHeight(height, normalOptions(kernel, strength, EdgeMode::Clamp));
    for (int y = 2; y < 30; ++y) {
      for (int x = 2; x < 30; ++x) {
        ASSERT_LT(angleDeg(decoded(normals, x, y), expected), 1e-3) << int(kernel);
      }
    }
  }
  // Higher ground to the right: the normal leans left; higher up the image: it leans down.
  EXPECT_LT(expected.x, 0.0);
  EXPECT_LT(expected.y, 0.0);
}

// On h = A sin(k x) sin(k row), each kernel is a linear filter, so its gradient is the exact
// gradient times the kernel's frequency response: the derivative's (sin k / k for central
// differences, (2 sin 2k + 4 sin k) / 8k for the 5-tap one) times the cross smoothing's
// (cos^2(k/2) for Sobel's 1 2 1, (10 + 6 cos k)/16 for Scharr's 3 10 3, (6 + 8 cos k + 2 cos 2k)
// / 16 for 1 4 6 4 1). The generated normals must match that prediction to float precision, and
// their error against the exact normals is what the response predicts.
struct Response {
  double derivative;
  double smoothing;
};

Response responseOf(GradientKernel kernel, double k) {
  switch (kernel) {
    case GradientKernel::Central:
      return {std::sin(k) / k, 1.0};
    case GradientKernel::Sobel:
      return {std::sin(k) / k, std::pow(std::cos(k / 2.0), 2.0)};
    case GradientKernel::Scharr:
      return {std::sin(k) / k, (10.0 + 6.0 * std::cos(k)) / 16.0};
    case GradientKernel::Sobel5:
      return {(2.0 * std::sin(2.0 * k) + 4.0 * std::sin(k)) / (8.0 * k),
              (6.0 + 8.0 * std::cos(k) + 2.0 * std::cos(2.0 * k)) / 16.0};
  }
  return {1.0, 1.0};
}

TEST(NormalFromHeight, KernelsMatchTheirFrequencyResponseOnSines) {
  const int size = 64;
  const double k = 2.0 * kPi / 16.0;  // a 16-texel period: detail where kernels differ
  const double amplitude = 0.5, strength = 2.0;
  const Image height = field(size, size, [](int x, int row, int, int) {
    return 0.5 + 0.5 * std::sin(2.0 * kPi / 16.0 * x) * std::sin(2.0 * kPi / 16.0 * row);
  });
  for (GradientKernel kernel : kKernels) {
    const Image normals =
        normalMapFromHeight(height, normalOptions(kernel, float(strength), EdgeMode::Wrap));
    const Response response = responseOf(kernel, k);
    const double multiplier = response.derivative * response.smoothing;
    double worstExact = 0.0, worstPredicted = 0.0;
    for (int row = 0; row < size; ++row) {
      for (int x = 0; x < size; ++x) {
        const double dhdx = amplitude * k * std::cos(k * x) * std::sin(k * row);
        const double dhdyUp = -amplitude * k * std::sin(k * x) * std::cos(k * row);
        const glm::dvec3 exact(-strength * dhdx, -strength * dhdyUp, 1.0);
        const glm::dvec3 predicted(-strength * dhdx * multiplier, -strength * dhdyUp * multiplier,
                                   1.0);
        const glm::dvec3 generated = decoded(normals, x, row);
        worstExact = std::max(worstExact, angleDeg(generated, exact));
        worstPredicted = std::max(worstPredicted, angleDeg(generated, predicted));
      }
    }
    // Float arithmetic only: the implementation is the kernel its response describes.
    EXPECT_LT(worstPredicted, 0.01) << "kernel " << int(kernel);
    // The error against the exact normal is the response's: at this 16-texel detail central
    // differences lose 2.6% of the slope, Scharr 5.3%, Sobel 6.3%, Sobel 5x5 13% (about 0.5,
    // 1.0, 1.2 and 2.6 degrees at the steepest slope); the bounds allow that plus float.
    const double slope = strength * amplitude * k;  // the steepest slope of the field
    const double bound = glm::degrees(std::atan(slope) - std::atan(slope * multiplier)) + 0.01;
    EXPECT_LT(worstExact, bound) << "kernel " << int(kernel);
  }
}

TEST(NormalFromHeight, DirectXDiffersExactlyInTheSignOfY) {
  const Image height = field(40, 24, [](int x, int row, int, int) {
    return 0.5 + 0.3 * std::sin(0.3 * x) * std::cos(0.2 * row);
  });
  NormalFromHeightOptions gl = normalOptions(GradientKernel::Scharr, 5.0f, EdgeMode::Wrap);
  NormalFromHeightOptions dx = gl;
  dx.convention = NormalConvention::DirectX;
  const Image a = normalMapFromHeight(height, gl);
  const Image b = normalMapFromHeight(height, dx);
  for (std::size_t p = 0; p < a.pixelCount(); ++p) {
    ASSERT_EQ(a.data()[p * 3], b.data()[p * 3]);
    ASSERT_NEAR(2.0f * a.data()[p * 3 + 1] - 1.0f, -(2.0f * b.data()[p * 3 + 1] - 1.0f), 1e-6f);
    ASSERT_EQ(a.data()[p * 3 + 2], b.data()[p * 3 + 2]);
  }
}

// Rolls an image by (dx, dy) with wrap-around.
Image rolled(const Image& image, int dx, int dy) {
  Image result(image.width(), image.height(), image.channels());
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const float* in = image.pixel(x, y);
      float* out = result.pixel((x + dx) % image.width(), (y + dy) % image.height());
      for (int c = 0; c < image.channels(); ++c)
        out[c] = in[c];
    }
  }
  return result;
}

TEST(Generators, WrapTilesWithoutASeam) {
  // With wrap-around edges the result of a shifted map is the shifted result, texel for texel:
  // the old borders are in the middle now and nothing changes there.
  const Image height = field(48, 32, [](int x, int row, int w, int h) {
    return 0.5 + 0.4 * std::sin(2.0 * kPi * x / w) * std::cos(4.0 * kPi * row / h) +
           0.1 * std::sin(6.0 * kPi * x / w);
  });
  for (GeneratorKind kind : {GeneratorKind::Normal, GeneratorKind::AmbientOcclusion,
                             GeneratorKind::Curvature, GeneratorKind::HeightFromColor}) {
    GeneratorRequest plain{kind, {&height}, {}, 1.0};
    const Image shiftedInput = rolled(height, 20, 11);
    GeneratorRequest shifted{kind, {&shiftedInput}, {}, 1.0};
    Result<GeneratedMap> a = runGenerator(plain);
    Result<GeneratedMap> b = runGenerator(shifted);
    ASSERT_TRUE(a.ok() && b.ok());
    const Image expected = rolled(a->image, 20, 11);
    for (std::size_t i = 0; i < expected.valueCount(); ++i) {
      ASSERT_NEAR(b->image.data()[i], expected.data()[i], 1e-5f)
          << generatorInfo(kind).name << " value " << i;
    }
  }
}

TEST(Generators, ClampBringsNothingInFromTheOtherSide) {
  // Flat at 0 except a steep rise in the last columns: wrapped, the first column would see it.
  const Image height = field(32, 16, [](int x, int, int w, int) { return x >= w - 3 ? 1.0 : 0.0; });
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const Image clamped =
      normalMapFromHeight(height, normalOptions(GradientKernel::Sobel5, 4.0f, EdgeMode::Clamp));
  const Image wrapped =
      normalMapFromHeight(height, normalOptions(GradientKernel::Sobel5, 4.0f, EdgeMode::Wrap));
  for (int y = 0; y < 16; ++y) {
    EXPECT_LT(angleDeg(decoded(clamped, 0, y), up), 1e-4);
    EXPECT_GT(angleDeg(decoded(wrapped, 0, y), up), 5.0);
  }
}

double correlation(const Image& a, const Image& b) {
  double ma = 0, mb = 0;
  const std::size_t n = a.pixelCount();
  for (std::size_t i = 0; i < n; ++i) {
    ma += a.data()[i * std::size_t(a.channels())];
    mb += b.data()[i * std::size_t(b.channels())];
  }
  ma /= double(n);
  mb /= double(n);
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = a.data()[i * std::size_t(a.channels())] - ma;
    const double y = b.data()[i * std::size_t(b.channels())] - mb;
    ab += x * y;
    aa += x * x;
    bb += y * y;
  }
  return ab / std::sqrt(aa * bb);
}

TEST(Generators, HeightNormalHeightRecoversATileableField) {
  const Image height = field(128, 96, [](int x, int row, int w, int h) {
    return 0.5 + 0.25 * std::sin(2.0 * kPi * x / w) * std::sin(4.0 * kPi * row / h) +
           0.2 * std::cos(6.0 * kPi * x / w + 2.0 * kPi * row / h);
  });
  GeneratorValues normalValues = defaultGeneratorValues(GeneratorKind::Normal);
  normalValues[std::size_t(findGeneratorOption(GeneratorKind::Normal, "strength"))] = 8.0;
  Result<GeneratedMap> normals =
      runGenerator({GeneratorKind::Normal, {&height}, normalValues, 1.0});
  ASSERT_TRUE(normals.ok());
  GeneratorValues heightValues = defaultGeneratorValues(GeneratorKind::Height);
  heightValues[std::size_t(findGeneratorOption(GeneratorKind::Height, "edge"))] = 0.0;  // wrap
  Result<GeneratedMap> recovered =
      runGenerator({GeneratorKind::Height, {&normals->image}, heightValues, 1.0});
  ASSERT_TRUE(recovered.ok()) << recovered.error();
  EXPECT_GE(correlation(height, recovered->image), 0.99);
  // The relief's depth: strength x the field's height range (0.89 here), in texels.
  ASSERT_TRUE(recovered->depthTexels.has_value());
  double low = 1e9, high = -1e9;
  for (std::size_t i = 0; i < height.pixelCount(); ++i) {
    low = std::min(low, double(height.data()[i]));
    high = std::max(high, double(height.data()[i]));
  }
  EXPECT_NEAR(*recovered->depthTexels, 8.0 * (high - low), 0.1 * 8.0 * (high - low));
}

TEST(Generators, HeightFromNormalOfANonTileableFieldHasNoWrapAround) {
  // A ramp: as a periodic field it would be a sawtooth with a cliff at the border.
  const Image height = field(96, 64, [](int x, int row, int w, int h) {
    return 0.8 * x / (w - 1.0) + 0.1 * std::sin(5.0 * row / h);
  });
  GeneratorValues normalValues = defaultGeneratorValues(GeneratorKind::Normal);
  normalValues[std::size_t(findGeneratorOption(GeneratorKind::Normal, "edge"))] = 1.0;  // clamp
  normalValues[std::size_t(findGeneratorOption(GeneratorKind::Normal, "strength"))] = 20.0;
  Result<GeneratedMap> normals =
      runGenerator({GeneratorKind::Normal, {&height}, normalValues, 1.0});
  ASSERT_TRUE(normals.ok());
  Result<GeneratedMap> recovered =
      runGenerator({GeneratorKind::Height, {&normals->image}, {}, 1.0});
  ASSERT_TRUE(recovered.ok());  // default edge: clamp, mirror-padded
  EXPECT_GE(correlation(height, recovered->image), 0.99);
  // Right up to the borders, the recovered height is the field (both normalised to 0..1): a
  // periodic integration would bend both border columns toward each other.
  double low = 1e9, high = -1e9;
  for (std::size_t i = 0; i < height.pixelCount(); ++i) {
    low = std::min(low, double(height.data()[i]));
    high = std::max(high, double(height.data()[i]));
  }
  for (int y = 0; y < 64; ++y) {
    for (int x : {0, 1, 94, 95}) {
      const double truth = (height.at(x, y, 0) - low) / (high - low);
      EXPECT_NEAR(recovered->image.at(x, y, 0), truth, 0.03) << "column " << x << " row " << y;
    }
  }
}

TEST(Generators, AmbientOcclusionIsOneOnAFlatFieldAndLowerInAPitThanOnAPeak) {
  const Image flat = field(32, 32, [](int, int, int, int) { return 0.5; });
  Result<GeneratedMap> open = runGenerator({GeneratorKind::AmbientOcclusion, {&flat}, {}, 1.0});
  ASSERT_TRUE(open.ok());
  for (std::size_t i = 0; i < open->image.valueCount(); ++i)
    ASSERT_EQ(open->image.data()[i], 1.0f);

  // A bump and a dent of the same shape, side by side.
  const Image peak = field(64, 32, [](int x, int row, int, int) {
    const double bump = (x - 16.0) * (x - 16.0) + (row - 16.0) * (row - 16.0);
    const double dent = (x - 48.0) * (x - 48.0) + (row - 16.0) * (row - 16.0);
    return 0.5 + 0.5 * std::exp(-bump / 18.0) - 0.5 * std::exp(-dent / 18.0);
  });
  Result<GeneratedMap> ao = runGenerator({GeneratorKind::AmbientOcclusion, {&peak}, {}, 1.0});
  ASSERT_TRUE(ao.ok());
  const float onPeak = ao->image.at(16, 16, 0);
  const float inPit = ao->image.at(48, 16, 0);
  EXPECT_GT(onPeak, 0.99f);  // nothing rises above the top
  EXPECT_LT(inPit, onPeak - 0.2f);
}

TEST(Generators, CurvatureIsBrightOnDomesAndDarkInPitsFromHeightAndFromNormals) {
  const Image bumps = field(64, 32, [](int x, int row, int, int) {
    const double a = (x - 16.0) * (x - 16.0) + (row - 16.0) * (row - 16.0);
    const double b = (x - 48.0) * (x - 48.0) + (row - 16.0) * (row - 16.0);
    return 0.5 + 0.4 * std::exp(-a / 30.0) - 0.4 * std::exp(-b / 30.0);
  });
  Result<GeneratedMap> fromHeight = runGenerator({GeneratorKind::Curvature, {&bumps}, {}, 1.0});
  ASSERT_TRUE(fromHeight.ok());
  EXPECT_GT(fromHeight->image.at(16, 16, 0), 0.55f);
  EXPECT_LT(fromHeight->image.at(48, 16, 0), 0.45f);
  EXPECT_NEAR(fromHeight->image.at(32, 2, 0), 0.5f, 0.02f);

  Result<GeneratedMap> normals = runGenerator({GeneratorKind::Normal, {&bumps}, {}, 1.0});
  ASSERT_TRUE(normals.ok());
  GeneratorValues values = defaultGeneratorValues(GeneratorKind::Curvature);
  values[std::size_t(findGeneratorOption(GeneratorKind::Curvature, "from"))] = 1.0;  // normal
  Result<GeneratedMap> fromNormal =
      runGenerator({GeneratorKind::Curvature, {&normals->image}, values, 1.0});
  ASSERT_TRUE(fromNormal.ok());
  EXPECT_GT(fromNormal->image.at(16, 16, 0), 0.55f);
  EXPECT_LT(fromNormal->image.at(48, 16, 0), 0.45f);
}

TEST(Generators, HeightFromColorRemovesLightingAndInverts) {
  // A texture of stripes under a strong left-to-right lighting gradient.
  Image photo(128, 32, 3, ColorSpace::Linear);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 128; ++x) {
      const float stripe = (x / 4) % 2 ? 0.1f : -0.1f;
      for (int c = 0; c < 3; ++c)
        photo.at(x, y, c) = 0.2f + 0.5f * x / 127.0f + stripe;
    }
  }
  GeneratorValues values = defaultGeneratorValues(GeneratorKind::HeightFromColor);
  values[std::size_t(findGeneratorOption(GeneratorKind::HeightFromColor, "radius"))] = 8.0;
  Result<GeneratedMap> height =
      runGenerator({GeneratorKind::HeightFromColor, {&photo}, values, 1.0});
  ASSERT_TRUE(height.ok());
  // The gradient is gone: stripes look alike on both sides.
  const float left = height->image.at(20, 16, 0) - height->image.at(24, 16, 0);
  const float right = height->image.at(100, 16, 0) - height->image.at(104, 16, 0);
  EXPECT_NEAR(left, right, 0.02f);
  EXPECT_NEAR(height->image.at(20, 16, 0) + height->image.at(24, 16, 0), 1.0f, 0.05f);
  values[std::size_t(findGeneratorOption(GeneratorKind::HeightFromColor, "invert"))] = 1.0;
  Result<GeneratedMap> inverted =
      runGenerator({GeneratorKind::HeightFromColor, {&photo}, values, 1.0});
  ASSERT_TRUE(inverted.ok());
  EXPECT_NEAR(inverted->image.at(20, 16, 0), 1.0f - height->image.at(20, 16, 0), 1e-6f);
}

TEST(Generators, PackingPutsTheLevelledHeightInAlphaAndTheMaterialCanCompensate) {
  const Image height = field(16, 8, [](int x, int, int, int) { return 0.3 + 0.02 * x; });
  Image normals(16, 8, 3);
  for (std::size_t i = 0; i < normals.valueCount(); ++i)
    normals.data()[i] = (i % 3 == 2) ? 1.0f : 0.5f;
  Result<GeneratedMap> packed = runGenerator({GeneratorKind::Pack, {&normals, &height}, {}, 1.0});
  ASSERT_TRUE(packed.ok()) << packed.error();
  ASSERT_EQ(packed->image.channels(), 4);
  ASSERT_TRUE(packed->levels.has_value());
  EXPECT_NEAR(packed->levels->low, 0.3, 1e-6);
  EXPECT_NEAR(packed->levels->high, 0.6, 1e-6);
  EXPECT_NEAR(packed->image.at(0, 0, 3), 0.0f, 1e-6f);
  EXPECT_NEAR(packed->image.at(15, 0, 3), 1.0f, 1e-6f);
  // The relief is unchanged: h' * scale' + bias' equals h * scale + bias everywhere.
  const HeightCompensation compensation = compensateLevels(*packed->levels, 0.04, -0.04);
  for (int x = 0; x < 16; ++x) {
    const double before = height.at(x, 0, 0) * 0.04 - 0.04;
    const double after =
        packed->image.at(x, 0, 3) * compensation.heightScale + compensation.heightBias;
    EXPECT_NEAR(after, before, 1e-6);
  }
  // The swizzle form gives the same channels.
  Result<Image> swizzled = swizzleChannels({&normals, &height}, "nh", "n.r n.g n.b h.r");
  ASSERT_TRUE(swizzled.ok());
  EXPECT_EQ(swizzled->at(5, 3, 3), height.at(5, 3, 0));
  EXPECT_FALSE(swizzleChannels({&normals, &height}, "nh", "n.r x.g").ok());
  EXPECT_FALSE(swizzleChannels({&normals, &height}, "nh", "n.q").ok());
}

// Any map channel, inverse or constant into any channel; the named layouts put each map where
// the engines' documentation says (glTF 2.0 / Unreal ORM: R occlusion, G roughness, B metallic;
// Unity HDRP mask map: R metallic, G occlusion, B detail mask, A smoothness = 1 - roughness),
// with neutral values for the maps a material lacks.
TEST(Generators, ChannelPackingPutsEveryMapWhereTheLayoutSays) {
  Image ao(8, 4, 1), roughness(8, 4, 1), colour(8, 4, 3);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      ao.at(x, y, 0) = 0.1f * float(x);
      roughness.at(x, y, 0) = 0.05f * float(y + x);
      for (int c = 0; c < 3; ++c)
        colour.at(x, y, c) = 0.01f * float(10 * c + x);
    }
  }
  const std::vector<NamedMap> maps = {{"ao", &ao}, {"roughness", &roughness}, {"color", &colour}};
  Result<Image> custom = packChannels(maps, {"color.b", "1-roughness.r", "0.25", "ao.g"});
  ASSERT_TRUE(custom.ok()) << custom.error();
  ASSERT_EQ(custom->channels(), 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      EXPECT_FLOAT_EQ(custom->at(x, y, 0), colour.at(x, y, 2));
      EXPECT_FLOAT_EQ(custom->at(x, y, 1), 1.0f - roughness.at(x, y, 0));
      EXPECT_FLOAT_EQ(custom->at(x, y, 2), 0.25f);
      EXPECT_FLOAT_EQ(custom->at(x, y, 3), ao.at(x, y, 0));  // a grey map's g is its only channel
    }
  }
  EXPECT_FALSE(packChannels(maps, {"ao.r", "1.5"}).ok());            // constant outside 0..1
  EXPECT_FALSE(packChannels(maps, {"metallic.r"}).ok());             // no such map
  EXPECT_FALSE(packChannels(maps, {"ao.x"}).ok());                   // no such channel
  EXPECT_FALSE(packChannels(maps, {"0", "0", "0", "0", "0"}).ok());  // five channels
  Image small(4, 4, 1);
  EXPECT_FALSE(packChannels({{"ao", &ao}, {"small", &small}}, {"ao.r", "small.r"}).ok());

  std::vector<std::string> substituted;
  const std::vector<std::string> mask =
      resolveLayoutTerms(*findPackLayout("unity-mask"), maps, &substituted);
  EXPECT_EQ(mask, (std::vector<std::string>{"0", "ao.r", "1", "1-roughness.r"}));
  EXPECT_EQ(substituted, std::vector<std::string>{"metallic"});
  Result<Image> packed = packChannels(maps, mask);
  ASSERT_TRUE(packed.ok()) << packed.error();
  EXPECT_FLOAT_EQ(packed->at(3, 2, 0), 0.0f);
  EXPECT_FLOAT_EQ(packed->at(3, 2, 1), ao.at(3, 2, 0));
  EXPECT_FLOAT_EQ(packed->at(3, 2, 2), 1.0f);
  EXPECT_FLOAT_EQ(packed->at(3, 2, 3), 1.0f - roughness.at(3, 2, 0));
  // ORM without maps: occlusion 1, roughness 1, metallic 0; a flat normal is (0.5, 0.5, 1).
  EXPECT_EQ(resolveLayoutTerms(*findPackLayout("orm"), {}),
            (std::vector<std::string>{"1", "1", "0"}));
  EXPECT_EQ(resolveLayoutTerms(*findPackLayout("normal-height"), {}),
            (std::vector<std::string>{"0.5", "0.5", "1", "0"}));
  EXPECT_EQ(findPackLayout("nope"), nullptr);
}

// Unpacking is packing's inverse: an ORM texture gives back its three maps with the channel
// each came from, a Unity mask map gives roughness from its smoothness, and an image with
// fewer channels than the layout reads is refused with the channel it lacks.
TEST(Generators, UnpackingALayoutGivesBackTheMapsPackedIntoIt) {
  const Image ao = field(8, 4, [](int x, int, int, int) { return 0.1 * x; });
  const Image roughness = field(8, 4, [](int x, int y, int, int) { return 0.05 * (x + y); });
  const Image metallic = field(8, 4, [](int, int y, int, int) { return y / 3.0; });
  const std::vector<NamedMap> maps = {
      {"ao", &ao}, {"roughness", &roughness}, {"metallic", &metallic}};
  for (const char* name : {"orm", "unity-mask"}) {
    const PackLayout& layout = *findPackLayout(name);
    Result<Image> packed = packChannels(maps, resolveLayoutTerms(layout, maps));
    ASSERT_TRUE(packed.ok()) << packed.error();
    Result<std::vector<UnpackedMap>> unpacked = unpackLayout(packed.value(), layout);
    ASSERT_TRUE(unpacked.ok()) << unpacked.error();
    ASSERT_EQ(unpacked->size(), 3u) << name;  // the mask map's detail constant is no map
    for (const UnpackedMap& map : unpacked.value()) {
      const Image& original = map.name == "ao"          ? ao
                              : map.name == "roughness" ? roughness
                                                        : metallic;
      ASSERT_EQ(map.image.channels(), 1);
      for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x)
          EXPECT_NEAR(map.image.at(x, y, 0), original.at(x, y, 0), 1e-6) << name << " " << map.name;
      }
    }
  }
  Result<std::vector<UnpackedMap>> orm = unpackLayout(
      packChannels(maps, {"ao.r", "roughness.r", "metallic.r"}).value(), *findPackLayout("orm"));
  ASSERT_TRUE(orm.ok());
  EXPECT_EQ(orm.value()[0].name, "ao");
  EXPECT_EQ(orm.value()[0].channel, 0);
  EXPECT_EQ(orm.value()[1].name, "roughness");
  EXPECT_EQ(orm.value()[1].channel, 1);
  EXPECT_EQ(orm.value()[2].name, "metallic");
  EXPECT_EQ(orm.value()[2].channel, 2);
  Result<std::vector<UnpackedMap>> grey = unpackLayout(ao, *findPackLayout("orm"));
  ASSERT_FALSE(grey.ok());
  EXPECT_NE(grey.error().find("channel G"), std::string::npos) << grey.error();
}

// The pack generator in an engine layout takes any subset of its maps: the Unity mask map from
// an AO map alone is metallic 0, occlusion, detail 1 and smoothness 0 (roughness neutral 1),
// with notes naming the maps that were missing; height in normal alpha still needs both maps.
TEST(Generators, PackInAnEngineLayoutTakesWhicheverMapsAreGiven) {
  const Image ao = field(16, 8, [](int x, int, int, int) { return x / 15.0; });
  GeneratorValues values = defaultGeneratorValues(GeneratorKind::Pack);
  values[std::size_t(findGeneratorOption(GeneratorKind::Pack, "layout"))] = 2;  // unity-mask
  Result<GeneratedMap> mask =
      runGenerator({GeneratorKind::Pack, {nullptr, nullptr, &ao, nullptr}, values, 1.0});
  ASSERT_TRUE(mask.ok()) << mask.error();
  ASSERT_EQ(mask->image.channels(), 4);
  for (int x = 0; x < 16; ++x) {
    EXPECT_FLOAT_EQ(mask->image.at(x, 3, 0), 0.0f);
    EXPECT_FLOAT_EQ(mask->image.at(x, 3, 1), ao.at(x, 3, 0));
    EXPECT_FLOAT_EQ(mask->image.at(x, 3, 2), 1.0f);
    EXPECT_FLOAT_EQ(mask->image.at(x, 3, 3), 0.0f);
  }
  ASSERT_EQ(mask->notes.size(), 2u);
  EXPECT_NE(mask->notes[0].find("no metallic map"), std::string::npos) << mask->notes[0];
  EXPECT_NE(mask->notes[1].find("no roughness map"), std::string::npos) << mask->notes[1];
  EXPECT_FALSE(runGenerator({GeneratorKind::Pack, {nullptr, &ao, nullptr, nullptr}, {}, 1.0}).ok());
}

TEST(Generators, BadInputWarnsOrFailsClearlyButNeverCrashes) {
  // A colour "photograph" given as a normal map: a warning, and the generator still runs.
  Image photo(64, 64, 3, ColorSpace::Srgb);
  for (std::size_t i = 0; i < photo.valueCount(); ++i)
    photo.data()[i] = float((i * 7919) % 256) / 255.0f;
  const auto warning = normalMapWarning(photo);
  ASSERT_TRUE(warning.has_value());
  EXPECT_NE(warning->find("normal map"), std::string::npos);
  EXPECT_TRUE(runGenerator({GeneratorKind::Height, {&photo}, {}, 1.0}).ok());
  // A real normal map passes.
  const Image height = field(32, 32, [](int x, int, int, int) { return 0.01 * x; });
  Result<GeneratedMap> normals = runGenerator({GeneratorKind::Normal, {&height}, {}, 1.0});
  ASSERT_TRUE(normals.ok());
  EXPECT_FALSE(normalMapWarning(normals->image).has_value());

  // 1x1 and non-square maps through every generator.
  for (auto [w, h] : {std::pair{1, 1}, std::pair{37, 13}, std::pair{3, 200}}) {
    Image grey(w, h, 1);
    Image rgb(w, h, 3);
    for (std::size_t i = 0; i < rgb.valueCount(); ++i)
      rgb.data()[i] = (i % 3 == 2) ? 1.0f : 0.5f;
    for (const GeneratorInfo& info : allGenerators()) {
      std::vector<const Image*> inputs;
      for (const GeneratorInput& input : info.inputs) {
        inputs.push_back(input.defaultSlot == MapSlot::Normal ? &rgb : &grey);
      }
      Result<GeneratedMap> result = runGenerator({info.kind, inputs, {}, 1.0});
      ASSERT_TRUE(result.ok()) << info.name << " " << w << "x" << h << ": " << result.error();
      EXPECT_EQ(result->image.width(), w);
      EXPECT_EQ(result->image.height(), h);
    }
  }
  // Missing inputs are an error, not a crash.
  EXPECT_FALSE(runGenerator({GeneratorKind::Pack, {&height}, {}, 1.0}).ok());
  EXPECT_FALSE(runGenerator({GeneratorKind::Normal, {nullptr}, {}, 1.0}).ok());
}

TEST(Generators, AnEightKMapWorks) {
  Image big(8192, 8192, 1);
  for (int y = 0; y < 8192; y += 64) {
    for (int x = 0; x < 8192; ++x)
      big.at(x, y, 0) = 1.0f;  // stripes every 64 rows
  }
  Result<GeneratedMap> normals = runGenerator({GeneratorKind::Normal, {&big}, {}, 1.0});
  ASSERT_TRUE(normals.ok());
  EXPECT_EQ(normals->image.width(), 8192);
  // Rows beside a stripe tilt; rows between stripes are flat.
  EXPECT_LT(decoded(normals->image, 100, 1).y, 0.0);
  EXPECT_NEAR(decoded(normals->image, 100, 32).z, 1.0, 1e-6);
}

TEST(Generators, CancelStopsTheWork) {
  const Image height = field(256, 256, [](int x, int, int, int) { return 0.01 * x; });
  std::atomic<bool> cancel{true};
  WorkControl control;
  control.cancel = &cancel;
  for (const GeneratorInfo& info : allGenerators()) {
    std::vector<const Image*> inputs(info.inputs.size(), &height);
    Result<GeneratedMap> result = runGenerator({info.kind, inputs, {}, 1.0}, control);
    if (info.kind == GeneratorKind::Pack)
      continue;  // instant, nothing to cancel
    EXPECT_FALSE(result.ok()) << info.name;
  }
}

}  // namespace
}  // namespace relief::core
