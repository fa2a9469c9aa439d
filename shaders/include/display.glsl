// The display transform (core/view/DisplayTransform.h has the same in C++): exposure, then the
// tone mapper, of linear radiance; the sRGB encoding follows (color.glsl).

// Khronos PBR Neutral (Khronos Group 2024, github.com/KhronosGroup/ToneMapping, PBR_Neutral):
// F90 = 0.04, compression from Ks = 0.8 - F90, desaturation speed Kd = 0.15.
vec3 pbrNeutral(vec3 color) {
  const float kF90 = 0.04;
  const float kStart = 0.8 - kF90;
  const float kDesaturation = 0.15;
  float darkest = min(color.r, min(color.g, color.b));
  float offset = darkest <= 2.0 * kF90 ? darkest - darkest * darkest / (4.0 * kF90) : kF90;
  vec3 lowered = color - offset;
  float peak = max(lowered.r, max(lowered.g, lowered.b));
  if (peak <= kStart) return lowered;
  float newPeak = 1.0 - (1.0 - kStart) * (1.0 - kStart) / (peak + 1.0 - 2.0 * kStart);
  float keep = 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
  return lowered * (newPeak / peak) * keep + vec3(newPeak) * (1.0 - keep);
}

vec3 displayTransform(vec3 radiance) {
  vec3 exposed = max(radiance, vec3(0.0)) * uExposure;
  return uToneMapper == 1 ? pbrNeutral(exposed) : exposed;
}
