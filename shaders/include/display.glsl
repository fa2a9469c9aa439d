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

// ACES filmic as Stephen Hill fitted it (BakingLab ACES.hlsl), after the 1/0.6 exposure of the
// glTF Sample Viewer and three.js. GLSL's mat3 takes columns: these are the rows transposed.
vec3 acesFilmic(vec3 color) {
  const mat3 kIn = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566,
                        0.83777);
  const mat3 kOut = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367,
                         -0.00605, 1.07602);
  vec3 v = kIn * (color / 0.6);
  vec3 curved = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
  return clamp(kOut * curved, 0.0, 1.0);
}

vec3 displayTransform(vec3 radiance) {
  vec3 exposed = max(radiance, vec3(0.0)) * uExposure;
  if (uToneMapper == 1) return pbrNeutral(exposed);
  if (uToneMapper == 2) return acesFilmic(exposed);
  return exposed;
}
