// Displacement technique, tessellation evaluation: each generated vertex moves along the
// surface normal to its height, s = h * heightScale + heightBias UV units (the convention of
// every technique, references 000 and 004), turned into world units by the mesh's world length
// per UV unit (core::worldUnitsPerUv, one factor for the whole mesh so edges stay shared).
// Shading then reads the normal map at the vertex's UV in the undisplaced tangent frame, as the
// other techniques do at their visible point.

#include "include/material_inputs.glsl"
#include "include/height_source.glsl"

layout(triangles, equal_spacing, ccw) in;

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
} vOut;


// Points inside the patch: the barycentric blend of its three vertices.
vec2 blend(vec2 a, vec2 b, vec2 c) {
  return gl_TessCoord.x * a + gl_TessCoord.y * b + gl_TessCoord.z * c;
}
vec3 blend(vec3 a, vec3 b, vec3 c) {
  return gl_TessCoord.x * a + gl_TessCoord.y * b + gl_TessCoord.z * c;
}
vec4 blend(vec4 a, vec4 b, vec4 c) {
  return gl_TessCoord.x * a + gl_TessCoord.y * b + gl_TessCoord.z * c;
}

// Points on a patch edge are shared with the neighbouring patch, which meets them with the
// edge's vertices the other way round (the GL's tessellation invariance rules make the points
// along an edge the same from either side, their two weights summing to exactly 1). Evaluating
// them from the vertex that comes first in an order both patches agree on (its world position),
// by the weight of the other vertex as the tessellator gave it, with `precise` so that no fused
// multiply-add differs, gives both bit-identical points: no pinholes open between patches.
bool comesFirst(int a, int b) {
  vec3 pa = vIn[a].worldPosition, pb = vIn[b].worldPosition;
  return pa.x != pb.x ? pa.x < pb.x : (pa.y != pb.y ? pa.y < pb.y : pa.z <= pb.z);
}

struct EdgePoint {
  vec3 position;
  vec3 normal;
  vec2 uv;
};

EdgePoint edgePoint(int a, int b, float weightA, float weightB) {
  int from = comesFirst(a, b) ? a : b;
  int to = from == a ? b : a;
  float t = from == a ? weightB : weightA;
  EdgePoint point;
  precise vec3 position =
      vIn[from].worldPosition + t * (vIn[to].worldPosition - vIn[from].worldPosition);
  precise vec3 normal = vIn[from].worldNormal + t * (vIn[to].worldNormal - vIn[from].worldNormal);
  precise vec2 uv = vIn[from].uv + t * (vIn[to].uv - vIn[from].uv);
  point.position = position;
  point.normal = normal;
  point.uv = uv;
  return point;
}

void main() {
  vec3 position = blend(vIn[0].worldPosition, vIn[1].worldPosition, vIn[2].worldPosition);
  vec3 normal = blend(vIn[0].worldNormal, vIn[1].worldNormal, vIn[2].worldNormal);
  vec2 uv = blend(vIn[0].uv, vIn[1].uv, vIn[2].uv);
  vec3 weights = gl_TessCoord;
  int corner = weights.x == 1.0 ? 0 : (weights.y == 1.0 ? 1 : (weights.z == 1.0 ? 2 : -1));
  if (corner >= 0) {  // a vertex of the mesh, exactly as the vertex stage left it
    // The index is clamped although the branch excludes -1: llvmpipe runs a branch for all of
    // its SIMD lanes and does not mask indirect input loads, so lanes whose corner is -1 read
    // vIn[-1], before its input buffer (an intermittent SEGV in its JIT code, seen under
    // AddressSanitizer in the displacement tests).
    int vertex = max(corner, 0);
    position = vIn[vertex].worldPosition;
    normal = vIn[vertex].worldNormal;
    uv = vIn[vertex].uv;
  } else if (weights.x == 0.0 || weights.y == 0.0 || weights.z == 0.0) {
    // On the edge opposite the vertex whose weight is 0.
    EdgePoint point = weights.z == 0.0   ? edgePoint(0, 1, weights.x, weights.y)
                      : weights.x == 0.0 ? edgePoint(1, 2, weights.y, weights.z)
                                         : edgePoint(2, 0, weights.z, weights.x);
    position = point.position;
    normal = point.normal;
    uv = point.uv;
  }
  // Level 0: the vertices are point samples of the bilinear surface the exact tracer meets.
  // The control stage never splits finer than a quarter texel; where a segment spans texels
  // (far away, or at the tessellation cap) the geometry is coarser than the map, as any
  // tessellated displacement is.
  float h = heightFromTexel(textureLod(HEIGHT_SOURCE_MAP, mapCoordinates(uv * uTiling), 0.0));
  float s = h * uHeightScale + uHeightBias;  // UV units of one repeat of the maps
  position += normalize(normal) * (s * uWorldPerUv / uTiling);

  vOut.worldPosition = position;
  vOut.uv = uv;
  vOut.worldNormal = normal;
  vOut.worldTangent = blend(vIn[0].worldTangent, vIn[1].worldTangent, vIn[2].worldTangent);
  vOut.uvScale = blend(vIn[0].uvScale, vIn[1].uvScale, vIn[2].uvScale);
  gl_Position = uViewProjection * vec4(position, 1.0);
}
