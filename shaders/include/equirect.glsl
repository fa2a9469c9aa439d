// Equirectangular (latitude-longitude) maps, as core/shading/EnvironmentMaps.h lays them out:
// row 0 (t = 0) is the zenith (+Y), the centre column looks toward -Z.
//   u = atan(d.x, -d.z) / 2pi + 0.5,  v = acos(d.y) / pi
// Sampled with textureLod only: the u seam (atan's jump from pi to -pi) would give implicit
// derivatives a one-pixel line of the coarsest mip level.

#include "constants.glsl"

vec2 equirectUv(vec3 direction) {
  vec3 d = normalize(direction);
  return vec2(atan(d.x, -d.z) * (0.5 / kPi) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / kPi);
}

vec3 equirectDirection(vec2 uv) {
  float azimuth = (uv.x - 0.5) * 2.0 * kPi;
  float polar = uv.y * kPi;
  return vec3(sin(polar) * sin(azimuth), cos(polar), -sin(polar) * cos(azimuth));
}
