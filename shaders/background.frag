// The viewport's background. BACKGROUND_COLOR: a quiet vertical gradient, neutral grey so it
// does not tint judgement of colour and dark so highlights read clearly. Otherwise the
// environment seen along each pixel's eye ray: the source radiance at the level that matches
// the pixel's size (BACKGROUND_ENVIRONMENT), or the prefiltered chain at the level of
// kBlurredRoughness (BACKGROUND_BLURRED), through the same display transform as the material.

#include "include/color.glsl"

in vec2 vScreen;
out vec4 fragColor;

uniform vec3 uTopColor;     // linear RGB
uniform vec3 uBottomColor;  // linear RGB

#ifndef BACKGROUND_COLOR
#include "include/environment.glsl"

uniform float uExposure;
uniform int uToneMapper;
#include "include/display.glsl"

uniform mat4 uInverseViewProjection;
uniform vec3 uCameraPosition;
uniform sampler2D uEnvironmentSource;
uniform vec2 uEnvironmentSourceSize;
uniform float uPixelAngle;  // radians a pixel spans vertically

const float kBlurredRoughness = 0.5;
#endif

void main() {
#ifdef BACKGROUND_COLOR
  fragColor = vec4(linearToSrgb(mix(uBottomColor, uTopColor, vScreen.y)), 1.0);
#else
  vec4 far = uInverseViewProjection * vec4(vScreen * 2.0 - 1.0, 1.0, 1.0);
  vec3 direction = far.xyz / far.w - uCameraPosition;
#ifdef BACKGROUND_BLURRED
  vec3 radiance = environmentSpecular(direction, kBlurredRoughness);
#else
  float texelAngle = kPi / uEnvironmentSourceSize.y;
  float lod = max(log2(uPixelAngle / texelAngle), 0.0);
  vec2 uv = equirectUv(uEnvironmentRotation * direction);
  vec3 radiance = textureLod(uEnvironmentSource, uv, lod).rgb * uEnvironmentIntensity;
#endif
  fragColor = vec4(linearToSrgb(displayTransform(radiance)), 1.0);
#endif
}
