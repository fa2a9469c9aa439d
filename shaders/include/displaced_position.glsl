// World position of the visible (displaced) surface point, for the depth offset and the depth
// view. The parallax result is a move in tangent space measured in texture UV units; screen-
// space derivatives give the world-space vectors of one UV unit along u and v at this pixel.

struct UvToWorld {
  vec3 dpdu;          // world displacement per unit of texture u
  vec3 dpdv;          // ... of texture v
  float worldPerUv;   // their mean length: heights (UV units) to world units
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
    result.worldPerUv = 0.0;
    return result;
  }
  result.dpdu = (dpdx * duvdy.y - dpdy * duvdx.y) / determinant;
  result.dpdv = (dpdy * duvdx.x - dpdx * duvdy.x) / determinant;
  result.worldPerUv = 0.5 * (length(result.dpdu) + length(result.dpdv));
  return result;
}

vec3 displacedWorldPosition(UvToWorld frame, vec3 worldPosition, vec2 uvMove,
                            float surfaceHeight, vec3 normal) {
  return worldPosition + frame.dpdu * uvMove.x + frame.dpdv * uvMove.y +
         normal * (surfaceHeight * frame.worldPerUv);
}
