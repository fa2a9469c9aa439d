// Which map holds the height and how one of its texels reads as h (0..1, 1 the top of the
// relief). Kept apart from height.glsl, whose mip query exists in fragment shaders only, so
// the tessellation stage (material.tese) reads heights the same way.

#ifdef HEIGHT_IN_NORMAL_ALPHA
#define HEIGHT_SOURCE_MAP uNormalMap
#else
#define HEIGHT_SOURCE_MAP uHeightMap
#endif

float heightFromTexel(vec4 texel) {
#ifdef HEIGHT_IN_NORMAL_ALPHA
  float h = texel.a;
#else
  float h = texel.r;
#endif
  return uHeightIsDepth ? 1.0 - h : h;
}
