// Height lookups. h is 0..1 with 1 the top of the relief (DESIGN.md, reference 001); the
// surface lies s = h * scale + bias UV units above the mesh. Gradients are passed in, so the
// lookups can run inside dynamic loops (textureGrad in sampleMap, reference 001).

#include "height_source.glsl"
#ifdef HEX_TILING
#include "hex_tiling.glsl"
#endif

float sampleHeight(vec2 uv, vec2 dx, vec2 dy) {
#ifdef HEX_TILING
  HexTaps taps = hexTaps(uv, dx, dy);
  return dot(taps.weight, taps.heights);
#else
  return heightFromTexel(sampleMap(HEIGHT_SOURCE_MAP, uv, dx, dy));
#endif
}

// The same lookup at a given mip level (textureLod): where the level is known, as in the exact
// tracers' minified refinement, it skips textureGrad's per-lookup level selection, which
// llvmpipe computes in software.
float sampleHeightAtLevel(vec2 uv, float level) {
#ifdef HEX_TILING
  HexTaps taps = hexTapsAtLevel(uv, level);
  return dot(taps.weight, taps.heights);
#else
  return heightFromTexel(textureLod(HEIGHT_SOURCE_MAP, mapCoordinates(uv), level));
#endif
}

// Mip level the height map is read at here (GLSL 4.00 textureQueryLod).
float heightMipLevel(vec2 uv) {
  return textureQueryLod(HEIGHT_SOURCE_MAP, mapCoordinates(uv)).x;
}
