// The prefiltered environment pbr shading and the background read (renderer/EnvironmentLight):
// a mip chain of GGX-prefiltered radiance, level i for perceptual roughness i / (levels - 1)
// (Karis 2013's split sum: the incoming light integrated under the GGX lobe with N = V = R),
// and the diffuse irradiance over pi, a radiance-like value (1 under a uniform environment of
// radiance 1). Directions are world space; the rotation turns them into the environment's.

#include "equirect.glsl"

uniform sampler2D uEnvironmentSpecular;
uniform sampler2D uEnvironmentIrradiance;
uniform float uEnvironmentMaxLevel;   // levels - 1: the level of roughness 1
uniform float uEnvironmentIntensity;  // factor on the radiance
uniform mat3 uEnvironmentRotation;    // world to environment directions

vec3 environmentSpecular(vec3 reflected, float roughness) {
  vec2 uv = equirectUv(uEnvironmentRotation * reflected);
  return textureLod(uEnvironmentSpecular, uv, roughness * uEnvironmentMaxLevel).rgb *
         uEnvironmentIntensity;
}

vec3 environmentIrradiance(vec3 normal) {
  vec2 uv = equirectUv(uEnvironmentRotation * normal);
  return textureLod(uEnvironmentIrradiance, uv, 0.0).rgb * uEnvironmentIntensity;
}
