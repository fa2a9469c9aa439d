// The glTF 2.0 BRDF; see Brdf.h.
#include "core/shading/Brdf.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace relief::core::inline shading {

double roughnessFromShininess(double shininess) {
  const double alphaSquared = 2.0 / (std::max(shininess, 0.0) + 2.0);
  return std::clamp(std::pow(alphaSquared, 0.25), 0.0, 1.0);
}

float ggxDistribution(float alpha, float nDotH) {
  if (nDotH <= 0.0f)
    return 0.0f;
  const float alpha2 = alpha * alpha;
  const float denominator = nDotH * nDotH * (alpha2 - 1.0f) + 1.0f;
  return alpha2 / (kPi * denominator * denominator);
}

float smithVisibility(float alpha, float nDotL, float nDotV) {
  const float alpha2 = alpha * alpha;
  const float ggxV = nDotL * std::sqrt(nDotV * nDotV * (1.0f - alpha2) + alpha2);
  const float ggxL = nDotV * std::sqrt(nDotL * nDotL * (1.0f - alpha2) + alpha2);
  const float sum = ggxV + ggxL;
  return sum > 0.0f ? 0.5f / sum : 0.0f;
}

float schlickWeight(float vDotH) {
  const float m = std::clamp(1.0f - std::abs(vDotH), 0.0f, 1.0f);
  return m * m * m * m * m;
}

glm::vec3 gltfBrdf(const glm::vec3& baseColor, float metallic, float roughness, const glm::vec3& n,
                   const glm::vec3& l, const glm::vec3& v) {
  const float nDotL = glm::dot(n, l);
  const float nDotV = glm::dot(n, v);
  if (nDotL <= 0.0f || nDotV <= 0.0f)
    return glm::vec3(0.0f);
  const glm::vec3 h = glm::normalize(l + v);
  const float alpha = roughness * roughness;
  const float specular =
      ggxDistribution(alpha, glm::dot(n, h)) * smithVisibility(alpha, nDotL, nDotV);
  const float weight = schlickWeight(glm::dot(v, h));
  // Dielectric: fresnel_mix(ior 1.5, base = diffuse, layer = specular).
  const float dielectricFresnel = kDielectricF0 + (1.0f - kDielectricF0) * weight;
  const glm::vec3 dielectric =
      (1.0f - dielectricFresnel) * baseColor / kPi + glm::vec3(dielectricFresnel * specular);
  // Metal: conductor_fresnel(f0 = baseColor, bsdf = specular).
  const glm::vec3 metalFresnel = baseColor + (glm::vec3(1.0f) - baseColor) * weight;
  const glm::vec3 metal = metalFresnel * specular;
  return dielectric + (metal - dielectric) * metallic;
}

}  // namespace relief::core::inline shading
