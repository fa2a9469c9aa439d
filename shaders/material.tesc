// Displacement technique, tessellation control: how finely each triangle is split before
// material.tese moves its vertices by the height. Each edge is split into segments about
// kTargetEdgePixels long on screen, never shorter than one texel of the height map (finer
// geometry could not show more of it) and at most uMaxTessellation of them. An edge's count
// depends on its two vertices only, so the triangles either side of it agree and no cracks open.

#include "include/material_inputs.glsl"

layout(vertices = 3) out;

in VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
} vIn[];

out VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
} vOut[];

uniform vec2 uViewportSize;  // pixels

const float kTargetEdgePixels = 4.0;

float edgeSegments(int a, int b) {
  vec4 clipA = gl_in[a].gl_Position;
  vec4 clipB = gl_in[b].gl_Position;
  // An edge reaching behind the eye has no screen length: split it as finely as allowed.
  float pixels = 1e9;
  if (clipA.w > 1e-6 && clipB.w > 1e-6)
    pixels = length((clipA.xy / clipA.w - clipB.xy / clipB.w) * 0.5 * uViewportSize);
  vec2 texels = abs(vIn[a].uv - vIn[b].uv) * uTiling * uHeightMapSize;
  float finest = max(texels.x, texels.y);
  return clamp(min(pixels / kTargetEdgePixels, finest), 1.0, float(uMaxTessellation));
}

void main() {
  vOut[gl_InvocationID].worldPosition = vIn[gl_InvocationID].worldPosition;
  vOut[gl_InvocationID].uv = vIn[gl_InvocationID].uv;
  vOut[gl_InvocationID].worldNormal = vIn[gl_InvocationID].worldNormal;
  vOut[gl_InvocationID].worldTangent = vIn[gl_InvocationID].worldTangent;
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0) {
    // Outer level i belongs to the edge opposite vertex i.
    gl_TessLevelOuter[0] = edgeSegments(1, 2);
    gl_TessLevelOuter[1] = edgeSegments(2, 0);
    gl_TessLevelOuter[2] = edgeSegments(0, 1);
    gl_TessLevelInner[0] =
        max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
