// SampleMaterials; see SampleMaterials.h. Distances are designed in texels of a 1024 map and
// scaled for other sizes, so every size shows the same material.
#include "SampleMaterials.h"

#include "ProceduralNoise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace relief::tools {
namespace {

using core::Image;

struct Rgb {
  float r, g, b;
};

Rgb scale(Rgb c, float s) {
  return {c.r * s, c.g * s, c.b * s};
}
Rgb mix(Rgb a, Rgb b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

// Rounded bevel: a quarter circle rising over `width` texels from the border.
float bevel(float distance, float width) {
  const float t = std::clamp(distance / width, 0.0f, 1.0f);
  return std::sqrt(1.0f - (1.0f - t) * (1.0f - t));
}

// Per-texel field evaluation at texel centres; `fill(u, v, colour, height)`.
template <class Fill>
SampleMaterial evaluate(const std::string& name, int size, Fill fill) {
  SampleMaterial sample;
  sample.name = name;
  sample.colorLinear = Image(size, size, 3, core::ColorSpace::Linear);
  sample.height = Image(size, size, 1, core::ColorSpace::Linear);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) / float(size);
      const float v = (float(y) + 0.5f) / float(size);
      Rgb color{0, 0, 0};
      float height = 0.0f;
      fill(u, v, color, height);
      float* c = sample.colorLinear.pixel(x, y);
      c[0] = std::clamp(color.r, 0.0f, 1.0f);
      c[1] = std::clamp(color.g, 0.0f, 1.0f);
      c[2] = std::clamp(color.b, 0.0f, 1.0f);
      sample.height.at(x, y, 0) = std::clamp(height, 0.0f, 1.0f);
    }
  }
  return sample;
}

// Three box-blur passes (close to a Gaussian of sigma ~ radius) with wrap-around, so the
// result still tiles.
void blurWrapped(Image& image, int radius) {
  const int width = image.width();
  const int height = image.height();
  std::vector<float> line;
  for (int pass = 0; pass < 3; ++pass) {
    for (int axis = 0; axis < 2; ++axis) {
      const int length = axis == 0 ? width : height;
      const int lines = axis == 0 ? height : width;
      line.resize(std::size_t(length));
      for (int l = 0; l < lines; ++l) {
        auto at = [&](int i) -> float& {
          const int w = ((i % length) + length) % length;
          return axis == 0 ? image.at(w, l, 0) : image.at(l, w, 0);
        };
        float sum = 0.0f;
        for (int i = -radius; i <= radius; ++i)
          sum += at(i);
        for (int i = 0; i < length; ++i) {
          line[std::size_t(i)] = sum / float(2 * radius + 1);
          sum += at(i + radius + 1) - at(i - radius);
        }
        for (int i = 0; i < length; ++i)
          at(i) = line[std::size_t(i)];
      }
    }
  }
}

}  // namespace

SampleMaterial makeBricks(int size) {
  constexpr int kColumns = 4;
  constexpr int kRows = 12;                   // running bond, alternate rows offset by half a brick
  const float texel = float(size) / 1024.0f;  // design texels -> this size's texels
  const float brickWidth = float(size) / kColumns;
  const float brickHeight = float(size) / kRows;
  const std::array<Rgb, 5> palette = {{{0.40f, 0.10f, 0.055f},
                                       {0.50f, 0.17f, 0.080f},
                                       {0.33f, 0.09f, 0.060f},
                                       {0.45f, 0.20f, 0.120f},
                                       {0.28f, 0.08f, 0.050f}}};
  SampleMaterial sample = evaluate("bricks", size, [&](float u, float v, Rgb& color, float& h) {
    const int row = int(std::floor(v * kRows));
    const float shifted = u + ((row % 2) ? 0.5f / kColumns : 0.0f);
    const int column = int(std::floor(shifted * kColumns));
    const auto id = std::uint32_t((column % kColumns) + kColumns * row);
    const float lx = (shifted * kColumns - float(column)) * brickWidth;
    const float ly = (v * kRows - float(row)) * brickHeight;
    const float chip = 2.5f * texel * fractalNoise(u, v, 32, 3, 0.5f, 11u);
    const float distance =
        std::min({lx, brickWidth - lx, ly, brickHeight - ly}) - 6.0f * texel + chip;

    const float tiltX = 0.06f * (unitHash(id, 3u, 1u) - 0.5f) * (lx / brickWidth - 0.5f);
    const float tiltY = 0.06f * (unitHash(id, 4u, 1u) - 0.5f) * (ly / brickHeight - 0.5f);
    const float pits = std::max(0.0f, fractalNoise(u, v, 48, 2, 0.5f, 17u) - 0.45f);
    const float top = 0.82f + 0.08f * (unitHash(id, 2u, 1u) - 0.5f) +
                      0.035f * fractalNoise(u, v, 16, 5, 0.55f, 13u) + tiltX + tiltY - 0.5f * pits;
    const float mortar = 0.18f + 0.04f * fractalNoise(u, v, 64, 3, 0.5f, 19u);
    const float rise = distance <= 0.0f ? 0.0f : bevel(distance, 8.0f * texel);
    h = mortar + (top - mortar) * rise;

    Rgb brick =
        scale(palette[hash(id, 5u, 1u) % palette.size()], 0.85f + 0.3f * unitHash(id, 6u, 1u));
    brick = scale(brick, 1.0f + 0.25f * fractalNoise(u, v, 8, 4, 0.5f, 23u));
    const float speckle = std::max(0.0f, fractalNoise(u, v, 128, 2, 0.5f, 29u) - 0.35f);
    brick = scale(brick, 1.0f - 1.2f * speckle - 1.5f * pits);
    brick = scale(brick, 0.75f + 0.25f * std::clamp(distance / (12.0f * texel), 0.0f, 1.0f));
    const Rgb mortarColor =
        scale(Rgb{0.32f, 0.30f, 0.27f}, 1.0f + 0.2f * fractalNoise(u, v, 96, 3, 0.5f, 31u));
    color = mix(mortarColor, brick, rise);
  });
  sample.heightScale = 0.03;
  sample.tiling = 2.0;
  sample.specular = 0.12;
  sample.shininess = 16.0;
  return sample;
}

SampleMaterial makeCobblestones(int size) {
  const float texel = float(size) / 1024.0f;
  const std::array<Rgb, 4> stones = {
      {{0.16f, 0.16f, 0.15f}, {0.22f, 0.20f, 0.17f}, {0.14f, 0.15f, 0.17f}, {0.26f, 0.24f, 0.21f}}};
  SampleMaterial sample =
      evaluate("cobblestones", size, [&](float u, float v, Rgb& color, float& h) {
        const VoronoiSample cell = voronoi(u, v, 8, 0.8f, 41u);
        const float gap = (4.0f + 2.0f * fractalNoise(u, v, 32, 2, 0.5f, 43u)) * texel;
        const float distance = cell.edgeDistance * float(size) - gap;
        const float dome = distance <= 0.0f ? 0.0f : bevel(distance, 30.0f * texel);
        // The stones' large shape only; rounded by the blur below, then detailed.
        const float top = 0.72f + 0.16f * (unitHash(cell.cellId, 1u, 2u) - 0.5f);
        h = 0.12f + (top - 0.12f) * dome;

        Rgb stone =
            scale(stones[cell.cellId % stones.size()], 0.8f + 0.4f * unitHash(cell.cellId, 3u, 2u));
        stone = scale(stone, 1.0f + 0.3f * fractalNoise(u, v, 32, 4, 0.5f, 59u));
        stone = scale(stone, 0.55f + 0.45f * dome);  // grime collects toward the joints
        const Rgb sandColor =
            scale(Rgb{0.20f, 0.16f, 0.11f}, 1.0f + 0.35f * fractalNoise(u, v, 128, 3, 0.5f, 61u));
        color = mix(sandColor, stone, std::min(1.0f, dome * 2.0f));
      });
  // A distance-to-border field has sharp ridges along the cells' medial axes (stones would look
  // like pyramids); blurring rounds them into domes. Surface detail is added after the blur.
  blurWrapped(sample.height, std::max(1, int(std::lround(10.0f * texel))));
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) / float(size);
      const float v = (float(y) + 0.5f) / float(size);
      float& h = sample.height.at(x, y, 0);
      const float detail = h > 0.2f ? 0.04f * fractalNoise(u, v, 24, 5, 0.5f, 47u)
                                    : 0.03f * fractalNoise(u, v, 96, 3, 0.5f, 53u);
      h = std::clamp(h + detail, 0.0f, 1.0f);
    }
  }
  sample.heightScale = 0.05;
  sample.tiling = 2.0;
  sample.specular = 0.2;
  sample.shininess = 24.0;
  return sample;
}

SampleMaterial makeTiles(int size) {
  constexpr int kTiles = 4;
  const float texel = float(size) / 1024.0f;
  const float tileSize = float(size) / kTiles;
  const Rgb cream{0.72f, 0.66f, 0.55f};
  const Rgb teal{0.03f, 0.16f, 0.15f};
  SampleMaterial sample = evaluate("tiles", size, [&](float u, float v, Rgb& color, float& h) {
    const int column = int(std::floor(u * kTiles));
    const int row = int(std::floor(v * kTiles));
    const auto id = std::uint32_t(column + kTiles * row);
    const float lx = (u * kTiles - float(column)) * tileSize;
    const float ly = (v * kTiles - float(row)) * tileSize;
    const float distance = std::min({lx, tileSize - lx, ly, tileSize - ly}) - 5.0f * texel;
    const float rise = distance <= 0.0f ? 0.0f : bevel(distance, 6.0f * texel);
    const float top = 0.86f + 0.02f * (unitHash(id, 1u, 3u) - 0.5f) +
                      0.015f * fractalNoise(u, v, 4, 3, 0.5f, 67u);
    const float grout = 0.35f + 0.03f * fractalNoise(u, v, 128, 2, 0.5f, 71u);
    h = grout + (top - grout) * rise;

    Rgb glaze = ((column + row) % 2) ? teal : cream;
    glaze = scale(glaze, 0.95f + 0.1f * unitHash(id, 2u, 3u));
    glaze = scale(glaze, 1.0f + 0.06f * fractalNoise(u, v, 16, 4, 0.5f, 73u));
    const Rgb groutColor =
        scale(Rgb{0.20f, 0.19f, 0.18f}, 1.0f + 0.25f * fractalNoise(u, v, 128, 2, 0.5f, 79u));
    color = mix(groutColor, glaze, rise);
  });
  sample.heightScale = 0.015;
  sample.tiling = 2.0;
  sample.specular = 0.6;
  sample.shininess = 96.0;
  return sample;
}

std::vector<SampleMaterial> makeAllSamples(int size) {
  std::vector<SampleMaterial> samples;
  samples.push_back(makeBricks(size));
  samples.push_back(makeCobblestones(size));
  samples.push_back(makeTiles(size));
  return samples;
}

}  // namespace relief::tools
