// The split-sum table; see SplitSumLut.h.
#include "core/shading/SplitSumLut.h"

#include "core/base/ParallelFor.h"
#include "core/shading/Brdf.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace relief::core::inline shading {
namespace {

// The i-th of n points of the Hammersley set in [0, 1)^2.
void hammersley(std::uint32_t i, std::uint32_t n, float& u, float& v) {
  std::uint32_t bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  u = (float(i) + 0.5f) / float(n);
  v = float(bits) * 2.3283064365386963e-10f;  // / 2^32
}

}  // namespace

SplitSumTerms integrateSplitSum(float nDotV, float roughness, int samples) {
  nDotV = std::clamp(nDotV, 1e-4f, 1.0f);
  const float alpha = std::max(roughness * roughness, 1e-4f);
  const glm::vec3 v(std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV);  // n = +z
  double scale = 0.0, bias = 0.0;
  const int count = std::max(samples, 1);
  for (int i = 0; i < count; ++i) {
    float u1 = 0.0f, u2 = 0.0f;
    hammersley(std::uint32_t(i), std::uint32_t(count), u1, u2);
    // A half vector drawn with density D(h) (N.H): cos^2 theta = (1 - u) / (1 + (alpha^2 - 1) u).
    const float cosTheta = std::sqrt((1.0f - u1) / (1.0f + (alpha * alpha - 1.0f) * u1));
    const float sinTheta = std::sqrt(std::max(1.0f - cosTheta * cosTheta, 0.0f));
    const float phi = 2.0f * kPi * u2;
    const glm::vec3 h(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
    const float vDotH = glm::dot(v, h);
    const glm::vec3 l = 2.0f * vDotH * h - v;
    const float nDotL = l.z;
    if (nDotL <= 0.0f || vDotH <= 0.0f)
      continue;
    // f cos / pdf with pdf(l) = D (N.H) / (4 V.H): the D cancels.
    const float weight = smithVisibility(alpha, nDotL, nDotV) * nDotL * 4.0f * vDotH / cosTheta;
    const float fresnel = schlickWeight(vDotH);
    scale += double((1.0f - fresnel) * weight);
    bias += double(fresnel * weight);
  }
  return {float(scale / count), float(bias / count)};
}

Image makeSplitSumLut(int size, int samples) {
  Image table(size, size, 4, ColorSpace::Linear);
  parallelFor(size, [&](int row) {
    const float roughness = (float(row) + 0.5f) / float(size);
    for (int column = 0; column < size; ++column) {
      const SplitSumTerms terms =
          integrateSplitSum((float(column) + 0.5f) / float(size), roughness, samples);
      float* texel = table.pixel(column, row);
      texel[0] = terms.scale;
      texel[1] = terms.bias;
    }
  });
  return table;
}

}  // namespace relief::core::inline shading
