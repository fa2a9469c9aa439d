// Prefilters an equirectangular environment for image-based light (renderer/EnvironmentLight),
// one target texel per fragment, the target being one level of the specular chain or the
// irradiance map.
//
// SPECULAR, by filtered importance sampling (Krivanek and Colbert, "Real-time Shading with
// Filtered Importance Sampling", GPU Gems 3 ch. 20): each sample reads the source's mip level
// whose texels cover the solid angle the sample stands for,
//   lod = 0.5 log2(omegaSample / omegaTexel) + 1,  omegaSample = 1 / (count * pdf),
// so a few hundred samples give a smooth result instead of noise. A mip texel averages an
// aligned block, so a small bright source (a sun) moves toward its block's centre by up to half
// a block: more samples (rougher levels get more) keep the level, and the shift, small.
// radiance under the GGX lobe of perceptual roughness uRoughness with N = V = R
// (Karis 2013, "Real Shading in Unreal Engine 4"): half vectors from GGX's distribution of
// normals, l the reflection of v about h, weighted by N.L. pdf(l) = D(h) (N.H) / (4 V.H), which
// is D / 4 with N = V. Roughness 0 is the source itself, read at the level of the target's size.
// Otherwise the irradiance: the cosine-weighted mean of the radiance over the hemisphere about
// the direction, E / pi, so a uniform environment of radiance 1 gives 1. It is smooth enough to
// integrate exactly over a small mip level of the source (every texel, no sampling).

#include "include/equirect.glsl"

out vec4 fragColor;

uniform sampler2D uSource;
uniform vec2 uSourceSize;    // texels of level 0
uniform vec2 uTargetSize;    // texels of the level being written
uniform float uSourceMaxLod;  // the source's last mip level
uniform float uRoughness;    // SPECULAR: perceptual roughness of this level
uniform int uSampleCount;     // SPECULAR
uniform float uIrradianceLod;  // otherwise: the source level integrated

// The Hammersley set, both coordinates at their strata's centres: no sample sits exactly on the
// lobe's axis (the radical inverse's 0), which would read a small bright source at the finest
// level and spike where the target looks straight at it.
vec2 hammersley(uint i, uint count) {
  float radicalInverse = float(bitfieldReverse(i)) * 2.3283064365386963e-10;
  return vec2((float(i) + 0.5) / float(count), radicalInverse + 0.5 / float(count));
}

// Solid angle of one source texel at level 0 around a direction: 2pi/W by pi/H, shrinking
// toward the poles with sin(polar). Floored at one row's worth so the poles do not blur away.
float sourceTexelSolidAngle(vec3 direction) {
  float sinPolar = max(sqrt(max(1.0 - direction.y * direction.y, 0.0)), 1.0 / uSourceSize.y);
  return 2.0 * kPi * kPi / (uSourceSize.x * uSourceSize.y) * sinPolar;
}

vec3 sampleSource(vec3 direction, float sampleSolidAngle) {
  float lod = 0.5 * log2(sampleSolidAngle / sourceTexelSolidAngle(direction)) + 1.0;
  return textureLod(uSource, equirectUv(direction), clamp(lod, 0.0, uSourceMaxLod)).rgb;
}

mat3 basisAbout(vec3 n) {
  vec3 up = abs(n.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 tangent = normalize(cross(up, n));
  return mat3(tangent, cross(n, tangent), n);
}

void main() {
  vec2 uv = gl_FragCoord.xy / uTargetSize;
  vec3 n = equirectDirection(uv);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
#ifdef SPECULAR
  uint count = uint(uSampleCount);
  if (uRoughness <= 0.0) {
    fragColor = vec4(textureLod(uSource, uv, max(log2(uSourceSize.x / uTargetSize.x), 0.0)).rgb,
                     1.0);
    return;
  }
  mat3 basis = basisAbout(n);
  float alpha = uRoughness * uRoughness;
  float alpha2 = alpha * alpha;
  for (uint i = 0u; i < count; ++i) {
    vec2 xi = hammersley(i, count);
    float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (alpha2 - 1.0) * xi.y));
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    float phi = 2.0 * kPi * xi.x;
    vec3 h = basis * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
    vec3 l = 2.0 * cosTheta * h - n;  // v = n, so v.h = n.h = cosTheta
    float nDotL = dot(n, l);
    if (nDotL <= 0.0) continue;
    float d = cosTheta * cosTheta * (alpha2 - 1.0) + 1.0;
    float distribution = alpha2 / (kPi * d * d);
    float pdf = distribution / 4.0;
    sum += sampleSource(l, 1.0 / (float(count) * pdf)) * nDotL;
    weight += nDotL;
  }
#else
  // Every texel of the source level uIrradianceLod, weighted by its solid angle and N.L: an
  // exact quadrature of the (smooth) cosine lobe, with no sampling pattern to alias.
  ivec2 size = textureSize(uSource, int(uIrradianceLod));
  float rowAngle = kPi / float(size.y);
  for (int y = 0; y < size.y; ++y) {
    float polar0 = float(y) * rowAngle;
    float solidAngle = (cos(polar0) - cos(polar0 + rowAngle)) * 2.0 * kPi / float(size.x);
    for (int x = 0; x < size.x; ++x) {
      vec2 texelUv = (vec2(x, y) + 0.5) / vec2(size);
      float nDotL = dot(n, equirectDirection(texelUv));
      if (nDotL <= 0.0) continue;
      sum += texelFetch(uSource, ivec2(x, y), int(uIrradianceLod)).rgb * nDotL * solidAngle;
    }
  }
  weight = kPi;  // the integral of N.L over the hemisphere
#endif
  fragColor = vec4(sum / max(weight, 1e-8), 1.0);
}
