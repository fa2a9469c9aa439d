// Self-shadowing (reference 003, section 1.3): from the visible point, march toward the light
// until the ray leaves the top of the relief. Hard: shadowed when the height field rises above
// the ray. Soft (after Tatarchuk's penumbra estimate): the steepest occluder seen along the
// light ray, as an angle, against the light's angular size gives the covered part of the
// light. Returns the shadowed fraction (0 lit, 1 fully shadowed) and counts samples.
//
// The ray starts above the surface's own quantisation. An 8-bit height map stores a gentle
// slope as a staircase of 1/255 steps and a flat tile top with a level or two of noise (JPEG);
// a ray that starts on it meets a one-step wall at once and the pixel shadows itself (acne:
// grey speckles and dashes on flat tops). It starts from the higher of the traced point and the
// filtered height there (a march's interpolated hit can lie a little inside the surface), raised
// by kShadowStartQuanta of the map's quantum (uHeightQuantum: 1/255 for 8 bits, 1/65535 for
// 16). In UV units the lift is that times the height scale, so it shrinks with the relief and
// never exceeds two levels of the map: no shadow an artist painted is lost.

const float kShadowStartQuanta = 2.0;
// Float maps have no quantum; this floor covers the march's own rounding.
const float kShadowMinQuantum = 1.0 / 4096.0;

float shadowRayStart(vec2 uv, float height, vec2 dx, vec2 dy, float mipLevel,
                     inout int samples) {
  ++samples;
  float filtered = sampleHeight(uv, dx, dy);
  // Minified, the exact tracers meet the filtered map as the marches do (filteredHitFrom in
  // bilinear_cell.glsl); they once returned a pyramid block's top, from which no shadow ray was
  // ever blocked, and shadows ended in a hard line where the map's first mip level began.
  float surface = max(height, filtered);
  return surface + kShadowStartQuanta * max(uHeightQuantum, kShadowMinQuantum);
}

float selfShadow(vec2 uv, float height, vec3 L, vec2 dx, vec2 dy, float scale, float mipLevel,
                 inout int samples) {
#if defined(SHADOW_HARD) || defined(SHADOW_SOFT)
  if (L.z <= 0.0) return 1.0;  // the light is below the surface's horizon
  if (scale <= 0.0) return 0.0;
  height = shadowRayStart(uv, height, dx, dy, mipLevel, samples);
  if (height >= 1.0) return 0.0;
  int steps = max(uShadowSamples, 1);
  float heightStep = (1.0 - height) / float(steps);
  // Welsh's limit drops the 1/L.z, so low lights do not stretch shadows across the surface.
  vec2 uvPerHeight = uShadowLimit ? scale * L.xy : scale * L.xy / max(L.z, 1e-4);
  vec2 uvStep = uvPerHeight * heightStep;
  float uvStepLength = max(length(uvStep), 1e-8);
  float steepest = -1e9;  // tangent of the highest occluder's angle above the light ray
  for (int i = 1; i <= steps; ++i) {
    float rayHeight = height + heightStep * float(i);
    float h = sampleHeight(uv + uvStep * float(i), dx, dy);
    ++samples;
#if defined(SHADOW_HARD)
    if (h > rayHeight) return 1.0;
#else
    float slope = (h - rayHeight) * scale / (uvStepLength * float(i));
    if (slope > steepest) {
      steepest = slope;
      if (atan(steepest) >= 0.5 * uShadowSoftness && steepest > 0.0) break;  // fully covered
    }
#endif
  }
#if defined(SHADOW_HARD)
  return 0.0;
#else
  float halfSize = 0.5 * uShadowSoftness;
  float angle = atan(steepest);
  if (halfSize < 1e-4) return angle > 0.0 ? 1.0 : 0.0;
  return clamp((angle + halfSize) / (2.0 * halfSize), 0.0, 1.0);
#endif
#else
  return 0.0;
#endif
}
