// The parallax techniques, one compiled per program (TECHNIQUE_* define). All find where the
// eye ray through the fragment meets the height field s(u, v) = h * scale + bias, in texture
// UV units. The ray enters at `uv` on the mesh surface and runs along -V (V toward the eye, in
// tangent space): at height s it is at uv + s * V.xy / V.z.

struct ParallaxResult {
  vec2 uv;       // texture UV of the visible surface point
  float height;  // normalised height (0..1) of that point
  int samples;   // height samples taken (the cost view)
};

// Kaneko (references 000, 004): T + h_scaled * V.xy / V.z, exact only for a flat field; the
// offset grows without bound at grazing angles.
ParallaxResult parallaxOffset(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale, float bias,
                              bool limited) {
  float h = sampleHeight(uv, dx, dy);
  float s = h * scale + bias;
  // Welsh's offset limiting (reference 000) drops the 1/V.z: the offset never exceeds s.
  vec2 offset = limited ? s * V.xy : s * V.xy / max(V.z, 1e-4);
  ParallaxResult result;
  result.uv = uv + offset;
  result.height = sampleHeight(result.uv, dx, dy);
  result.samples = 2;
  return result;
}

// The layers a march takes. Reference 001 names one sample per texel the ray crosses as the
// ideal: fewer and a wall thinner than a layer is stepped over, which shows as slices at grazing
// angles. The ray crosses scale * |V.xy| / V.z of the texture through the slab, counted in texels
// of the mip level the lookups read (a minified map needs no more than its level's texels);
// uSamplesPerTexel of them per texel, between min and max samples. With uSamplesPerTexel 0, the
// count is lerped from max to min by V.z (reference 001: lerp(max, min, dot(E, N))).
int marchLayers(vec3 V, float scale, float mipLevel) {
  float vz = max(V.z, 1e-4);
  if (uSamplesPerTexel <= 0.0)
    return max(int(mix(float(uMaxSamples), float(uMinSamples), clamp(vz, 0.0, 1.0))), 1);
  vec2 crossedTexels = scale * V.xy / vz * uHeightMapSize / exp2(max(mipLevel, 0.0));
  float wanted = ceil(length(crossedTexels) * uSamplesPerTexel);
  float fewest = float(max(min(uMinSamples, uMaxSamples), 1));
  float most = float(max(max(uMinSamples, uMaxSamples), 1));
  return int(clamp(wanted, fewest, most));
}

// Steep parallax, POM and relief mapping march the slab from the top (h = 1) down in equal
// height layers (marchLayers gives how many).
ParallaxResult marchHeightField(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale, float bias,
                                float mipLevel) {
  float vz = max(V.z, 1e-4);
  int layers = marchLayers(V, scale, mipLevel);
  float layerStep = 1.0 / float(layers);
  // UV per unit of normalised height: moving down one layer moves the ray by this times step.
  vec2 uvPerHeight = scale * V.xy / vz;
  vec2 topUv = uv + (scale + bias) * V.xy / vz;

  float rayHeight = 1.0;
  vec2 currentUv = topUv;
  vec2 previousUv = topUv;
  float previousSample = 1.0;
  float currentSample = 1.0;
  int samples = 0;
  // layers + 1 samples reach h = 0, so a field of heights >= 0 is always hit.
  for (int i = 0; i <= layers; ++i) {
    currentSample = sampleHeight(currentUv, dx, dy);
    ++samples;
    if (currentSample >= rayHeight) break;  // the loop exits as soon as the ray is below
    previousUv = currentUv;
    previousSample = currentSample;
    rayHeight -= layerStep;
    currentUv -= uvPerHeight * layerStep;
  }

  ParallaxResult result;
  result.samples = samples;
#if defined(TECHNIQUE_STEEP)
  // The first layer below the surface, without interpolation: the stair steps show. The
  // point returned is on the surface there (its sampled height), so shading and shadows start
  // from the surface, not from inside it.
  result.uv = currentUv;
  result.height = currentSample;
#elif defined(TECHNIQUE_POM)
  if (samples == 1) {
    result.uv = currentUv;
    result.height = rayHeight;
  } else {
    // Reference 001: intersect the ray with the line between the last two height samples.
    float delta1 = currentSample - rayHeight;
    float delta2 = (rayHeight + layerStep) - previousSample;
    float ratio = delta1 / max(delta1 + delta2, 1e-6);
    result.uv = ratio * previousUv + (1.0 - ratio) * currentUv;
    result.height = rayHeight + ratio * layerStep;
  }
#else  // TECHNIQUE_RELIEF
  // Relief mapping: binary search between the last layer above the surface and the first
  // below, then the line through the final bracket's two samples (as POM does for its one
  // bracket), which removes most of what the halving leaves.
  float above = rayHeight + layerStep;
  float below = rayHeight;
  float sampleAbove = previousSample;
  float sampleBelow = currentSample;
  if (samples == 1) above = below;
  for (int i = 0; i < uRefinementSteps && samples > 1; ++i) {
    float middle = 0.5 * (above + below);
    float h = sampleHeight(topUv - uvPerHeight * (1.0 - middle), dx, dy);
    ++result.samples;
    if (h >= middle) {
      below = middle;
      sampleBelow = h;
    } else {
      above = middle;
      sampleAbove = h;
    }
  }
  if (samples > 1) {
    float delta1 = sampleBelow - below;
    float delta2 = above - sampleAbove;
    float ratio = delta1 / max(delta1 + delta2, 1e-6);
    result.height = below + ratio * (above - below);
  } else {
    result.height = below;
  }
  result.uv = topUv - uvPerHeight * (1.0 - result.height);
#endif
  return result;
}

#ifdef CURVED_SILHOUETTES
#include "curved_march.glsl"
#endif

#if defined(TECHNIQUE_QUADTREE) || defined(TECHNIQUE_CONE)
#include "bilinear_cell.glsl"
#endif
#if defined(TECHNIQUE_QUADTREE)
#include "quadtree.glsl"
#elif defined(TECHNIQUE_CONE)
#include "cone.glsl"
#endif

ParallaxResult findVisiblePoint(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale, float bias,
                                float mipLevel) {
#if defined(TECHNIQUE_QUADTREE)
  return traceQuadtree(uv, V, dx, dy, scale, bias, mipLevel);
#elif defined(TECHNIQUE_CONE)
  return traceCones(uv, V, dx, dy, scale, bias, mipLevel);
#elif defined(TECHNIQUE_PARALLAX)
  return parallaxOffset(uv, V, dx, dy, scale, bias, false);
#elif defined(TECHNIQUE_PARALLAX_LIMITED)
  return parallaxOffset(uv, V, dx, dy, scale, bias, true);
#elif defined(TECHNIQUE_STEEP) || defined(TECHNIQUE_POM) || defined(TECHNIQUE_RELIEF)
#ifdef CURVED_SILHOUETTES
  return marchCurvedHeightField(uv, V, dx, dy, scale, bias, mipLevel);
#else
  return marchHeightField(uv, V, dx, dy, scale, bias, mipLevel);
#endif
#else  // TECHNIQUE_NORMAL, TECHNIQUE_DISPLACEMENT (its geometry is displaced: material.tese)
  ParallaxResult result;
  result.uv = uv;
  result.height = sampleHeight(uv, dx, dy);
  result.samples = 1;
  return result;
#endif
}
