// Height lookups. h is 0..1 with 1 the top of the relief (DESIGN.md, reference 001); the
// surface lies s = h * scale + bias UV units above the mesh. Gradients are passed in, so the
// lookups can run inside dynamic loops (textureGrad in sampleMap, reference 001).

float sampleHeight(vec2 uv, vec2 dx, vec2 dy) {
#ifdef HEIGHT_IN_NORMAL_ALPHA
  float h = sampleMap(uNormalMap, uv, dx, dy).a;
#else
  float h = sampleMap(uHeightMap, uv, dx, dy).r;
#endif
  return uHeightIsDepth ? 1.0 - h : h;
}

// Mip level the height map is read at here (GLSL 4.00 textureQueryLod).
float heightMipLevel(vec2 uv) {
#ifdef HEIGHT_IN_NORMAL_ALPHA
  return textureQueryLod(uNormalMap, mapCoordinates(uv)).x;
#else
  return textureQueryLod(uHeightMap, mapCoordinates(uv)).x;
#endif
}
