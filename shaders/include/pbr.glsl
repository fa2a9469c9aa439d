// The glTF 2.0 metallic-roughness BRDF (its specification's appendix B; core/shading/Brdf.h is
// the same in C++): GGX with alpha = roughness^2, height-correlated Smith visibility, Schlick
// Fresnel, Lambert diffuse; a dielectric (f0 0.04) mixes diffuse and specular by Fresnel, a metal
// tints the specular by its base colour, metallic mixes the two.
//
// Direct light: the directional light's irradiance is pi * colour * intensity, so that a white
// Lambert surface facing a light of intensity 1 shows 1, as under classic shading.
// Indirect light: the prefiltered environment (environment.glsl) through the split-sum table
// (Karis 2013) with multiple-scattering energy compensation (Fdez-Agüera, JCGT 2019), so a
// white furnace shows 1 at any roughness; AO darkens it. Self-shadowing darkens the direct
// light only.

#include "constants.glsl"
#include "environment.glsl"
#include "tangent_space.glsl"

const float kDielectricF0 = 0.04;

float ggxDistribution(float alpha, float nDotH) {
  float alpha2 = alpha * alpha;
  float d = nDotH * nDotH * (alpha2 - 1.0) + 1.0;
  return nDotH > 0.0 ? alpha2 / (kPi * d * d) : 0.0;
}

float smithVisibility(float alpha, float nDotL, float nDotV) {
  float alpha2 = alpha * alpha;
  float ggxV = nDotL * sqrt(nDotV * nDotV * (1.0 - alpha2) + alpha2);
  float ggxL = nDotV * sqrt(nDotL * nDotL * (1.0 - alpha2) + alpha2);
  float sum = ggxV + ggxL;
  return sum > 0.0 ? 0.5 / sum : 0.0;
}

float schlickWeight(float vDotH) {
  float m = clamp(1.0 - abs(vDotH), 0.0, 1.0);
  float m2 = m * m;
  return m2 * m2 * m;
}

// f(l, v) for unit n, l, v; the cosine is not included.
vec3 gltfBrdf(vec3 baseColor, float metallic, float roughness, vec3 n, vec3 l, vec3 v) {
  float nDotL = dot(n, l);
  float nDotV = dot(n, v);
  if (nDotL <= 0.0 || nDotV <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float alpha = roughness * roughness;
  float specular = ggxDistribution(alpha, dot(n, h)) * smithVisibility(alpha, nDotL, nDotV);
  float weight = schlickWeight(dot(v, h));
  float dielectricFresnel = kDielectricF0 + (1.0 - kDielectricF0) * weight;
  vec3 dielectric = (1.0 - dielectricFresnel) * baseColor / kPi + vec3(dielectricFresnel * specular);
  vec3 metal = (baseColor + (1.0 - baseColor) * weight) * specular;
  return mix(dielectric, metal, metallic);
}

// Light reflected from the environment, for unit world-space normal n and view v. Fdez-Agüera's
// split: single scattering sees the radiance prefiltered along the reflection; the energy it
// loses (multiple scattering) and the diffuse part see the irradiance. Under a uniform
// environment both are the same and the sum is exactly the white furnace's.
vec3 environmentLight(vec3 baseColor, float metallic, float roughness, float nDotV, vec3 n,
                      vec3 v) {
  vec2 ab = texture(uSplitSumLut, vec2(nDotV, roughness)).rg;
  vec3 f0 = mix(vec3(kDielectricF0), baseColor, metallic);
  vec3 diffuseColor = baseColor * (1.0 - metallic);
  vec3 singleScatter = f0 * ab.x + ab.y;  // FssEss
  float energy = ab.x + ab.y;             // Ess
  vec3 averageFresnel = f0 + (1.0 - f0) / 21.0;
  vec3 multipleScatter = singleScatter * averageFresnel / (1.0 - (1.0 - energy) * averageFresnel);
  vec3 multipleSpecular = multipleScatter * (1.0 - energy);
  vec3 diffuse = diffuseColor * (1.0 - singleScatter - multipleSpecular);
  vec3 radiance = environmentSpecular(reflect(-v, n), roughness);
  vec3 irradiance = environmentIrradiance(n);
  return singleScatter * radiance + (multipleSpecular + diffuse) * irradiance;
}

// `frame` turns the tangent-space normal and view into world space for the environment.
vec3 shadePbr(SurfaceSample surface, vec3 lightTangent, vec3 viewTangent, float shadow,
              TangentFrame frame) {
  vec3 n = surface.normal;
  vec3 l = normalize(lightTangent);
  vec3 v = normalize(viewTangent);
  float roughness = clamp(uRoughness * (uHasRoughnessMap ? surface.roughness : 1.0), 0.0, 1.0);
  // Below 0.03 the GGX lobe is narrower than a pixel's normals can resolve: clamp, as engines do.
  roughness = max(roughness, 0.03);
  // glTF's metallicFactor times the map's texel (its neutral texel is 1).
  float metallic = clamp(uMetallic * surface.metallic, 0.0, 1.0);
  float nDotL = max(dot(n, l), 0.0);
  // As classic shading: fade the direct light over the last degrees above the geometric horizon.
  float horizon = clamp(l.z * 8.0, 0.0, 1.0);
  float lit = horizon * (1.0 - uShadowStrength * shadow);
  vec3 direct = gltfBrdf(surface.albedo, metallic, roughness, n, l, v) * nDotL * kPi *
                uLightColor * lit;
  float nDotV = clamp(dot(n, v), 1e-4, 1.0);
  vec3 worldNormal = fromTangentSpace(frame, n);
  vec3 worldView = fromTangentSpace(frame, v);
  vec3 indirect = environmentLight(surface.albedo, metallic, roughness, nDotV, worldNormal,
                                   worldView) *
                  surface.occlusion;
  return direct + indirect;
}
