// The exact reference tracer against closed-form answers (flat and tilted fields), against an
// independent brute-force search on a random field, and for shadow rays beside a tall box.
#include "core/tracing/ReliefTracer.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>

namespace relief::core {
namespace {

Image fieldImage(int width, int height, float (*h)(int x, int row, int width, int height)) {
  Image image(width, height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      image.at(x, y, 0) = h(x, y, width, height);
  }
  return image;
}

glm::dvec3 viewFrom(double azimuthDeg, double elevationDeg) {
  const double a = glm::radians(azimuthDeg), e = glm::radians(elevationDeg);
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

TEST(ReliefTracer, FlatFieldHitsWhereTheRayReachesItsHeight) {
  const Image flat = fieldImage(16, 16, [](int, int, int, int) { return 0.25f; });
  const double scale = 0.05, bias = -0.05;
  const HeightField field(flat, 0, scale, bias, false);
  const double s = 0.25 * scale + bias;  // -0.0375: below the mesh surface
  for (double elevation : {90.0, 60.0, 20.0, 5.0}) {
    const glm::dvec3 v = viewFrom(30.0, elevation);
    const ViewRayHit hit = traceViewRay(field, {0.3, 0.6}, v);
    ASSERT_TRUE(hit.hit);
    // Kaneko's formula is exact on a flat field: T + s * V.xy / V.z.
    const glm::dvec2 expected = glm::dvec2(0.3, 0.6) + s * glm::dvec2(v.x, v.y) / v.z;
    EXPECT_NEAR(hit.uv.x, expected.x, 1e-4 / 16.0) << elevation;
    EXPECT_NEAR(hit.uv.y, expected.y, 1e-4 / 16.0) << elevation;
    EXPECT_NEAR(hit.height, s, 1e-12);
  }
}

TEST(ReliefTracer, TiltedPlaneMatchesTheLinePlaneIntersection) {
  // h rises linearly with u across the interior; bilinear interpolation of a linear function
  // is that function, so the field is exactly the plane s = a + b u between texel centres.
  const int size = 64;
  const Image ramp =
      fieldImage(size, size, [](int x, int, int w, int) { return (float(x) + 0.5f) / float(w); });
  const double scale = 0.1, bias = -0.1;
  const HeightField field(ramp, 0, scale, bias, false);
  const double b = scale;  // ds/du
  const double a = bias;   // s at u = 0
  for (double elevation : {80.0, 45.0, 20.0}) {
    const glm::dvec3 v = viewFrom(180.0 + 25.0, elevation);  // looking toward +u (uphill)
    const glm::dvec2 entry(0.45, 0.5);
    // Ray: uv = entry - V.xy t, s = -V.z t. Solve -V.z t = a + b (entry.x - V.x t).
    const double t = (a + b * entry.x) / (-v.z + b * v.x);
    const glm::dvec2 expected = entry - glm::dvec2(v.x, v.y) * t;
    const ViewRayHit hit = traceViewRay(field, entry, v);
    ASSERT_TRUE(hit.hit);
    EXPECT_NEAR(hit.uv.x * size, expected.x * size, 1e-4) << elevation;
    EXPECT_NEAR(hit.uv.y * size, expected.y * size, 1e-4) << elevation;
  }
}

// Brute force: march in steps of 1/1000 texel and bisect the first sign change of
// field.sample(ray) - ray height. Independent of the tracer's cell walk and quadratics.
glm::dvec2 bruteForceHit(const HeightField& field, glm::dvec2 entry, glm::dvec3 v) {
  const double tStart = -field.maximum() / v.z;
  const double tEnd = -field.minimum() / v.z;
  const double step = 1e-3 / (field.width() * std::max(std::hypot(v.x, v.y), 1e-3));
  auto g = [&](double t) {
    const glm::dvec2 uv = entry - glm::dvec2(v.x, v.y) * t;
    return field.sample(uv.x, uv.y) + v.z * t;
  };
  double previous = tStart;
  for (double t = tStart; t <= tEnd + step; t += step) {
    if (g(t) >= 0.0) {
      double low = previous, high = t;
      for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (low + high);
        (g(mid) >= 0.0 ? high : low) = mid;
      }
      return entry - glm::dvec2(v.x, v.y) * high;
    }
    previous = t;
  }
  return {NAN, NAN};
}

TEST(ReliefTracer, AgreesWithBruteForceOnARandomField) {
  Image noise(24, 24, 1);
  std::uint32_t state = 7u;
  for (std::size_t i = 0; i < noise.valueCount(); ++i) {
    state = state * 1664525u + 1013904223u;
    noise.data()[i] = float(state >> 8) / 16777216.0f;
  }
  const HeightField field(noise, 0, 0.08, -0.08, false);
  int checked = 0;
  for (int k = 0; k < 40; ++k) {
    const glm::dvec2 entry(0.1 + 0.02 * k, 0.9 - 0.017 * k);
    const glm::dvec3 v = viewFrom(37.0 * k, 15.0 + 1.7 * k);
    const ViewRayHit hit = traceViewRay(field, entry, v);
    ASSERT_TRUE(hit.hit);
    const glm::dvec2 expected = bruteForceHit(field, entry, v);
    // Texel units; the brute force resolves to 1e-3 texel steps then bisects.
    EXPECT_NEAR(hit.uv.x * 24.0, expected.x * 24.0, 1e-4) << "ray " << k;
    EXPECT_NEAR(hit.uv.y * 24.0, expected.y * 24.0, 1e-4) << "ray " << k;
    // The hit lies on the surface.
    EXPECT_NEAR(field.sample(hit.uv.x, hit.uv.y), hit.height, 1e-9);
    ++checked;
  }
  EXPECT_EQ(checked, 40);
}

TEST(ReliefTracer, DepthMapsAreInvertedAndRaysWrapAround) {
  const Image depth = fieldImage(8, 8, [](int, int, int, int) { return 0.0f; });  // all top
  const HeightField field(depth, 0, 0.1, -0.1, true);
  const ViewRayHit hit = traceViewRay(field, {0.99, 0.5}, viewFrom(180.0, 10.0));
  ASSERT_TRUE(hit.hit);
  // Depth 0 = height 1 = s 0: the surface itself; the hit is the entry point.
  EXPECT_NEAR(hit.uv.x, 0.99, 1e-9);
  // A ray crossing u = 1 continues into the repeated field.
  const Image stripes = fieldImage(8, 8, [](int x, int, int, int) { return x == 0 ? 1.0f : 0.0f; });
  const HeightField striped(stripes, 0, 0.1, -0.1, false);
  const ViewRayHit across = traceViewRay(striped, {0.95, 0.5}, viewFrom(180.0, 30.0));
  ASSERT_TRUE(across.hit);
  EXPECT_GT(across.uv.x, 1.0);  // it hit the first column of the next repeat
}

// A 32x32 field, zero everywhere except a tall box in the middle columns 14..17.
float boxField(int x, int row, int, int) {
  return (x >= 14 && x <= 17 && row >= 8 && row <= 23) ? 1.0f : 0.0f;
}

TEST(ReliefTracer, ABoxShadowsTheSideAwayFromTheLight) {
  const Image box = fieldImage(32, 32, boxField);
  const HeightField field(box, 0, 0.05, -0.05, false);
  const glm::dvec3 light = viewFrom(0.0, 30.0);  // toward +u, 30 degrees up
  const double floor = -0.05;
  // Left of the box (light comes from +u, beyond the box): shadowed near the box.
  const ShadowRayHit left = traceShadowRay(field, {12.0 / 32.0, 0.5}, floor, light);
  EXPECT_TRUE(left.occluded);
  EXPECT_GT(left.distance, 0.0);
  // Right of the box (between box and light): lit.
  EXPECT_FALSE(traceShadowRay(field, {20.0 / 32.0, 0.5}, floor, light).occluded);
  // Far left: the shadow ends (box height 0.05 at 30 degrees reaches 0.087 UV = 2.8 texels).
  EXPECT_FALSE(traceShadowRay(field, {4.0 / 32.0, 0.5}, floor, light).occluded);
  // The top of the box is lit.
  EXPECT_FALSE(traceShadowRay(field, {16.0 / 32.0, 0.5}, 0.0, light).occluded);
  // A light below the horizon shadows everything.
  EXPECT_TRUE(traceShadowRay(field, {20.0 / 32.0, 0.5}, floor, viewFrom(0.0, -5.0)).occluded);
}

}  // namespace
}  // namespace relief::core
