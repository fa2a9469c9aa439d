// Self-shadowing (reference 003, section 1.3): from the visible point, march toward the light
// until the ray leaves the top of the relief. Hard: shadowed when the height field rises above
// the ray. Soft (after Tatarchuk's penumbra estimate): the steepest occluder seen along the
// light ray, as an angle, against the light's angular size gives the covered part of the
// light. Returns the shadowed fraction (0 lit, 1 fully shadowed) and counts samples.

float selfShadow(vec2 uv, float height, vec3 L, vec2 dx, vec2 dy, float scale,
                 inout int samples) {
#if defined(SHADOW_HARD) || defined(SHADOW_SOFT)
  if (L.z <= 0.0) return 1.0;  // the light is below the surface's horizon
  if (height >= 1.0 || scale <= 0.0) return 0.0;
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
