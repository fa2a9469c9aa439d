// The glTF 2.0 metallic-roughness BRDF, as its specification's appendix B defines it: a GGX
// (Trowbridge-Reitz) microfacet distribution with alpha = roughness^2, the height-correlated
// Smith visibility term, Schlick's Fresnel, and a Lambert diffuse base; a dielectric mixes the
// diffuse base and the specular layer by Fresnel (f0 = 0.04, IOR 1.5), a metal tints the
// specular layer by its base colour, and metallic mixes the two. The shader's version is
// shaders/include/pbr.glsl; this one is the tests' and the split-sum table's reference.
#pragma once

#include <glm/vec3.hpp>

namespace relief::core::inline shading {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kDielectricF0 = 0.04f;  // ((1.5 - 1) / (1.5 + 1))^2

// The perceptual roughness whose GGX lobe matches a Blinn-Phong exponent's highlight:
// alpha^2 = 2 / (shininess + 2) (Walter et al. 2007, the Beckmann-Phong correspondence), and
// roughness = sqrt(alpha). Exports of classic materials and the preset migration use it.
double roughnessFromShininess(double shininess);

// D: alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2), for N.H > 0 (0 otherwise).
float ggxDistribution(float alpha, float nDotH);
// V = G / (4 N.L N.V), height-correlated Smith for GGX:
// 0.5 / (N.L sqrt((N.V)^2 (1 - alpha^2) + alpha^2) + N.V sqrt((N.L)^2 (1 - alpha^2) + alpha^2)).
float smithVisibility(float alpha, float nDotL, float nDotV);
// Schlick's Fresnel weight (1 - |V.H|)^5: F = f0 + (1 - f0) * weight.
float schlickWeight(float vDotH);

// The BRDF f(l, v) (per steradian, the cosine not included) of a surface with normal `n`, for
// unit vectors `l` toward the light and `v` toward the eye; zero when either is below.
glm::vec3 gltfBrdf(const glm::vec3& baseColor, float metallic, float roughness, const glm::vec3& n,
                   const glm::vec3& l, const glm::vec3& v);

}  // namespace relief::core::inline shading
