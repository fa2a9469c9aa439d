// Material vertex stage: world-space position, UV and tangent frame for the fragment stage.
// The frame is interpolated and re-orthonormalised per fragment (see material.frag).
// No #version here: the renderer prepends it with the feature #defines.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aTangent;  // xyz tangent, w handedness (reference 004)
layout(location = 4) in vec2 aUvScale;  // world units per unit of u and of v

uniform mat4 uModel;
uniform mat3 uNormalMatrix;  // inverse transpose of the model matrix's upper 3x3
uniform mat4 uViewProjection;

out VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
  vec2 uvScale;  // world units per unit of u and of v (core::Vertex::uvScale)
} vOut;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vOut.worldPosition = world.xyz;
  vOut.uv = aUv;
  vOut.worldNormal = uNormalMatrix * aNormal;
  // Tangents follow the surface, so they transform with the model matrix itself.
  vOut.worldTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w);
  vOut.uvScale = aUvScale * vec2(length(mat3(uModel) * aTangent.xyz),
                                 length(mat3(uModel) * cross(aNormal, aTangent.xyz)));
  gl_Position = uViewProjection * world;
}
