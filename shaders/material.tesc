// Displacement technique, tessellation control: how finely each triangle is split before
// material.tese moves its vertices by the height. Each edge is split into segments about
// kTargetEdgePixels long on screen, never shorter than 1/kSegmentsPerTexel of a texel of the
// height map, and at most uMaxTessellation of them. Vertices one texel apart would sample the
// bilinear surface only where four texels meet and cut the texels' curvature flat (measured:
// 0.14 texel mean UV error against the exact tracer on the cobblestones height at 64x64); a
// quarter texel apart they follow it. An edge's count depends on its two vertices only, so the
// triangles either side of it agree and no cracks open.

#include "include/material_inputs.glsl"

layout(vertices = 3) out;

in VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
  vec2 uvScale;  // world units per unit of u and of v (core::Vertex::uvScale)
} vIn[];

out VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
  vec2 uvScale;  // world units per unit of u and of v (core::Vertex::uvScale)
} vOut[];

uniform vec2 uViewportSize;  // pixels

const float kTargetEdgePixels = 4.0;
const float kSegmentsPerTexel = 4.0;

float edgeSegments(int a, int b) {
  vec4 clipA = gl_in[a].gl_Position;
  vec4 clipB = gl_in[b].gl_Position;
  // An edge reaching behind the eye has no screen length: split it as finely as allowed.
  float pixels = 1e9;
  if (clipA.w > 1e-6 && clipB.w > 1e-6)
    pixels = length((clipA.xy / clipA.w - clipB.xy / clipB.w) * 0.5 * uViewportSize);
  vec2 texels = abs(vIn[a].uv - vIn[b].uv) * uTiling * uHeightMapSize;
  float finest = kSegmentsPerTexel * max(texels.x, texels.y);
  return clamp(min(pixels / kTargetEdgePixels, finest), 1.0, float(uMaxTessellation));
}

// Whether the patch, displaced anywhere between the lowest and the highest surface, lies wholly
// beyond one plane of the view frustum. Such patches are dropped: off screen they would still
// be split by their (large) projected length. The displaced patch lies within the hull of its
// corners moved to both extremes along their normals.
bool outsideView() {
  float toWorld = uWorldPerUv / uTiling;
  float lowest = min(uHeightBias, uHeightScale + uHeightBias) * toWorld;
  float highest = max(uHeightBias, uHeightScale + uHeightBias) * toWorld;
  // Per plane of the frustum, how many of the six points lie beyond it.
  ivec3 beyondLow = ivec3(0);   // x < -w (left), y < -w (bottom), z < -w (near)
  ivec3 beyondHigh = ivec3(0);  // x > w (right), y > w (top), z > w (far)
  for (int i = 0; i < 3; ++i) {
    vec3 normal = normalize(vIn[i].worldNormal);
    for (int j = 0; j < 2; ++j) {
      vec3 world = vIn[i].worldPosition + normal * (j == 0 ? lowest : highest);
      vec4 clip = uViewProjection * vec4(world, 1.0);
      beyondLow += ivec3(lessThan(clip.xyz, vec3(-clip.w)));
      beyondHigh += ivec3(greaterThan(clip.xyz, vec3(clip.w)));
    }
  }
  return any(equal(beyondLow, ivec3(6))) || any(equal(beyondHigh, ivec3(6)));
}

void main() {
  vOut[gl_InvocationID].worldPosition = vIn[gl_InvocationID].worldPosition;
  vOut[gl_InvocationID].uv = vIn[gl_InvocationID].uv;
  vOut[gl_InvocationID].worldNormal = vIn[gl_InvocationID].worldNormal;
  vOut[gl_InvocationID].worldTangent = vIn[gl_InvocationID].worldTangent;
  vOut[gl_InvocationID].uvScale = vIn[gl_InvocationID].uvScale;
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0 && outsideView()) {
    // An outer level of 0 drops the patch.
    gl_TessLevelOuter[0] = 0.0;
    gl_TessLevelOuter[1] = 0.0;
    gl_TessLevelOuter[2] = 0.0;
    gl_TessLevelInner[0] = 0.0;
  } else if (gl_InvocationID == 0) {
    // Outer level i belongs to the edge opposite vertex i.
    gl_TessLevelOuter[0] = edgeSegments(1, 2);
    gl_TessLevelOuter[1] = edgeSegments(2, 0);
    gl_TessLevelOuter[2] = edgeSegments(0, 1);
    gl_TessLevelInner[0] =
        max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
