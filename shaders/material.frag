// Material fragment stage: builds the tangent frame, moves view and light into tangent space
// (reference 004: Vt = (T.V, B.V, N.V)) and shades with per-pixel Blinn-Phong normal mapping.

#include "include/material_inputs.glsl"
#include "include/tangent_space.glsl"
#include "include/normal_mapping.glsl"
#include "include/lighting.glsl"
#include "include/color.glsl"

in VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
} vIn;

out vec4 fragColor;

void main() {
  TangentFrame frame = buildTangentFrame(vIn.worldNormal, vIn.worldTangent, gl_FrontFacing);
  vec3 viewTangent = toTangentSpace(frame, normalize(uCameraPosition - vIn.worldPosition));
  vec3 lightTangent = toTangentSpace(frame, uLightDirection);

  vec2 uv = vIn.uv * uTiling;
  SurfaceSample surface;
  surface.normal = sampleNormalMap(uv);
  surface.albedo = texture(uColorMap, uv).rgb;  // sRGB texture: already linear here
  surface.occlusion = texture(uOcclusionMap, uv).r;
  surface.roughness = texture(uRoughnessMap, uv).r;

  vec3 linearColor = shadeBlinnPhong(surface, lightTangent, viewTangent);
  fragColor = vec4(linearToSrgb(linearColor), 1.0);
}
