// sRGB encoding for the output (IEC 61966-2-1); Relief writes sRGB values into plain RGBA8
// framebuffers so the viewport and offscreen renders match without GL_FRAMEBUFFER_SRGB.

vec3 linearToSrgb(vec3 linearColor) {
  vec3 c = clamp(linearColor, 0.0, 1.0);
  vec3 low = c * 12.92;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(high, low, lessThanEqual(c, vec3(0.0031308)));
}
