// Reading tangent-space normals: decode from [0, 1], apply the Y convention and the strength,
// renormalise (filtering shortens normals; DESIGN.md renormalises after every filter).

vec3 decodeNormal(vec3 encoded) {
  vec3 n = encoded * 2.0 - 1.0;
  if (uNormalYDown) n.y = -n.y;
  n.xy *= uNormalStrength;
  // A texel with no tilt and z <= 0 (a black texel) would give a zero vector; keep it upright.
  n.z = max(n.z, 1e-4);
  return normalize(n);
}

vec3 sampleNormalMap(vec2 uv, vec2 dx, vec2 dy) {
  vec3 encoded = sampleMap(uNormalMap, uv, dx, dy).rgb;
  if (uNormalTwoChannel) {
    // Two-channel formats store X and Y; Z = sqrt(1 - x^2 - y^2) (reference 003, eq. 2.1).
    vec2 xy = encoded.xy * 2.0 - 1.0;
    encoded.z = sqrt(max(0.0, 1.0 - dot(xy, xy))) * 0.5 + 0.5;
  }
  return decodeNormal(encoded);
}

#ifdef HEX_TILING
// The hexagons' normals blended as slopes (dh/du, dh/dv = -n.xy / n.z), as Mikkelsen 2022
// blends surface gradients: averaging the vectors themselves would flatten the bumps where the
// hexagons meet.
vec3 sampleNormalMapHex(HexTaps taps, vec2 dx, vec2 dy) {
  vec2 slope = vec2(0.0);
  for (int i = 0; i < 3; ++i) {
    vec3 n = sampleNormalMap(taps.uv[i], dx, dy);
    slope += taps.weight[i] * (-n.xy / n.z);
  }
  return normalize(vec3(-slope, 1.0));
}
#endif
