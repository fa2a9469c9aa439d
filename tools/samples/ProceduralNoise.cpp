// ProceduralNoise; see ProceduralNoise.h.
#include "ProceduralNoise.h"

#include <algorithm>
#include <cmath>

namespace relief::tools {
namespace {

int wrap(int i, int period) {
  return ((i % period) + period) % period;
}

float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lerp(float a, float b, float t) {
  return a + (b - a) * t;
}

// Dot product of the lattice point's pseudo-random unit gradient with the offset.
float gradientDot(int ix, int iy, int period, std::uint32_t seed, float dx, float dy) {
  const float angle =
      unitHash(std::uint32_t(wrap(ix, period)), std::uint32_t(wrap(iy, period)), seed) *
      6.28318530718f;
  return std::cos(angle) * dx + std::sin(angle) * dy;
}

}  // namespace

std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  // A few rounds of multiply-xorshift (after the murmur3 finaliser): cheap and well mixed.
  std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

float unitHash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  return float(hash(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

float gradientNoise(float u, float v, int period, std::uint32_t seed) {
  const float x = u * float(period);
  const float y = v * float(period);
  const float fx = std::floor(x);
  const float fy = std::floor(y);
  const int ix = int(fx);
  const int iy = int(fy);
  const float tx = x - fx;
  const float ty = y - fy;
  const float n00 = gradientDot(ix, iy, period, seed, tx, ty);
  const float n10 = gradientDot(ix + 1, iy, period, seed, tx - 1.0f, ty);
  const float n01 = gradientDot(ix, iy + 1, period, seed, tx, ty - 1.0f);
  const float n11 = gradientDot(ix + 1, iy + 1, period, seed, tx - 1.0f, ty - 1.0f);
  const float sx = fade(tx);
  // Perlin noise in 2D stays within about +-0.71; scale to about +-1.
  return 1.41f * lerp(lerp(n00, n10, sx), lerp(n01, n11, sx), fade(ty));
}

float fractalNoise(float u, float v, int basePeriod, int octaves, float gain, std::uint32_t seed) {
  float sum = 0.0f;
  float amplitude = 1.0f;
  float total = 0.0f;
  int period = basePeriod;
  for (int octave = 0; octave < octaves; ++octave) {
    sum += amplitude * gradientNoise(u, v, period, seed + std::uint32_t(octave) * 7919u);
    total += amplitude;
    amplitude *= gain;
    period *= 2;
  }
  return sum / total;
}

VoronoiSample voronoi(float u, float v, int period, float jitter, std::uint32_t seed) {
  const float x = u * float(period);
  const float y = v * float(period);
  const int cx = int(std::floor(x));
  const int cy = int(std::floor(y));
  auto featurePoint = [&](int i, int j, float& px, float& py) {
    const auto wi = std::uint32_t(wrap(i, period));
    const auto wj = std::uint32_t(wrap(j, period));
    px = float(i) + 0.5f + jitter * (unitHash(wi, wj, seed) - 0.5f);
    py = float(j) + 0.5f + jitter * (unitHash(wi, wj, seed + 1u) - 0.5f);
    return hash(wi, wj, seed + 2u);
  };
  // First pass: the nearest feature point.
  float bestX = 0.0f, bestY = 0.0f, best = 1e30f;
  std::uint32_t bestId = 0;
  for (int j = cy - 2; j <= cy + 2; ++j) {
    for (int i = cx - 2; i <= cx + 2; ++i) {
      float px = 0.0f, py = 0.0f;
      const std::uint32_t id = featurePoint(i, j, px, py);
      const float d = (px - x) * (px - x) + (py - y) * (py - y);
      if (d < best) {
        best = d;
        bestX = px;
        bestY = py;
        bestId = id;
      }
    }
  }
  // Second pass: the exact distance to the nearest border, measured along the line between
  // the nearest point and each neighbour (the border is their perpendicular bisector).
  float edge = 1e30f;
  for (int j = cy - 2; j <= cy + 2; ++j) {
    for (int i = cx - 2; i <= cx + 2; ++i) {
      float px = 0.0f, py = 0.0f;
      featurePoint(i, j, px, py);
      const float ex = px - bestX, ey = py - bestY;
      const float length = std::sqrt(ex * ex + ey * ey);
      if (length < 1e-6f)
        continue;
      const float midX = 0.5f * (px + bestX) - x, midY = 0.5f * (py + bestY) - y;
      edge = std::min(edge, (midX * ex + midY * ey) / length);
    }
  }
  VoronoiSample sample;
  sample.cellId = bestId;
  sample.edgeDistance = edge / float(period);
  sample.centerDistance = std::sqrt(best) / float(period);
  return sample;
}

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace relief::tools
