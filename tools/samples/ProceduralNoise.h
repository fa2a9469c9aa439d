// Deterministic, tileable noise for the sample materials: integer hashing (no std::rand or
// <random> distributions, whose output differs between standard libraries), periodic gradient
// noise, fractal sums of it and periodic Voronoi cells. Coordinates are UV in [0, 1).
#pragma once

#include <cstdint>

namespace relief::tools {

std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed);
// A uniform value in [0, 1) from a hash.
float unitHash(std::uint32_t x, std::uint32_t y, std::uint32_t seed);

// Gradient (Perlin-style) noise with `period` cells across the unit square, so it tiles.
// Roughly in [-1, 1].
float gradientNoise(float u, float v, int period, std::uint32_t seed);

// Sum of `octaves` gradient-noise layers, each with twice the period and `gain` times the
// amplitude of the last; normalised to roughly [-1, 1].
float fractalNoise(float u, float v, int basePeriod, int octaves, float gain, std::uint32_t seed);

struct VoronoiSample {
  std::uint32_t cellId = 0;     // identifies the nearest feature point
  float edgeDistance = 0.0f;    // UV distance to the nearest cell border
  float centerDistance = 0.0f;  // UV distance to the nearest feature point
};

// Periodic Voronoi cells: one jittered feature point per cell of a period x period grid.
VoronoiSample voronoi(float u, float v, int period, float jitter, std::uint32_t seed);

float smoothstep(float edge0, float edge1, float x);

}  // namespace relief::tools
