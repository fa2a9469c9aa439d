// World position of the visible (displaced) surface point, for the depth offset and the depth
// view. The parallax result is a move in tangent space measured in texture UV units; screen-
// space derivatives give the world-space vectors of one UV unit along u and v at this pixel.

struct UvToWorld {
  vec3 dpdu;          // world displacement per unit of texture u
  vec3 dpdv;          // ... of texture v
};

// Uses screen-space derivatives: call in uniform control flow (before any discard or loop).
UvToWorld uvToWorld(vec3 worldPosition, vec2 uv) {
  UvToWorld result;
  vec3 dpdx = dFdx(worldPosition);
  vec3 dpdy = dFdy(worldPosition);
  vec2 duvdx = dFdx(uv);
  vec2 duvdy = dFdy(uv);
  float determinant = duvdx.x * duvdy.y - duvdx.y * duvdy.x;
  if (abs(determinant) < 1e-14) {
    result.dpdu = vec3(0.0);
    result.dpdv = vec3(0.0);
    return result;
  }
  result.dpdu = (dpdx * duvdy.y - dpdy * duvdx.y) / determinant;
  result.dpdv = (dpdy * duvdx.x - dpdx * duvdy.x) / determinant;
  return result;
}

// A direction in the space the marches step in: texture (u, v) and height, heights in UV units
// that `heightToWorld` world units make (the mesh's one factor, core::worldUnitsPerUv, as the
// displacement technique uses it, over the tiling). `tangentDirection` is the direction in the
// tangent frame (unit axes); `uvScale` the world units of one tiled unit of u and of v at this
// point (core::Vertex::uvScale, interpolated, over the tiling). A world unit along the tangent
// is 1 / uvScale.x of u, along the bitangent 1 / uvScale.y of v, and along the normal
// 1 / heightToWorld of height, so the relief has one depth in world units over the whole mesh
// and its parallax moves as far as that depth moves it along each axis. On a sphere's equator
// the texels are twice as wide as tall, and the tangent frame's unit axes made the relief
// twice as deep seen along u as along v. Where the texels are square and as large as the mesh
// factor (the plane) it is the tangent-space direction itself, which also stands in where the
// scales are unknown. The texel shape comes from the vertices, not from screen-space
// derivatives: a 2x2 pixel quad across a UV seam or a triangle edge has none to give. Not
// normalised.
vec3 toUvHeightSpace(vec3 tangentDirection, vec2 uvScale, float heightToWorld) {
  if (uvScale.x <= 0.0 || uvScale.y <= 0.0 || heightToWorld <= 0.0) return tangentDirection;
  return vec3(tangentDirection.xy * (heightToWorld / uvScale), tangentDirection.z);
}

vec3 displacedWorldPosition(UvToWorld frame, vec3 worldPosition, vec2 uvMove,
                            float surfaceHeight, vec3 normal, float heightToWorld) {
  return worldPosition + frame.dpdu * uvMove.x + frame.dpdv * uvMove.y +
         normal * (surfaceHeight * heightToWorld);
}
