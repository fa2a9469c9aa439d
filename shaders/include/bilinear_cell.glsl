// What the exact tracers (quadtree.glsl, cone.glsl) share: the cells of the bilinear height
// field, which lie between texel centres (cell (i, j) spans texels i..i+1 and j..j+1, in texel
// units with rows top first, as the maps are stored), their corners, the blocks of the maximum
// pyramid over them, the eye ray in cell coordinates, and where it meets a cell's bilinear patch.

// The maximum-mipmap pyramid of the height (core/tracing/MaxMipPyramid.h): R32F, one level per
// pyramid level, nearest. Level k bounds the field over blocks of 2^k cells.
uniform sampler2D uHeightPyramid;
uniform int uHeightPyramidLevels;

// Wraps a cell index into the map, however many repeats away; GLSL's % is undefined for
// negative operands.
ivec2 wrapTexel(ivec2 texel, ivec2 size) {
  return texel - size * ivec2(floor(vec2(texel) / vec2(size)));
}

// The block of pyramid `level` holding level-0 cell `cell0` (not wrapped): its index in the
// level (`block`) and the level-0 cells [first, end) it spans in the repeat `cell0` lies in (the
// last block of a row or column runs to the map's edge). Returns the block's bound.
float pyramidBlock(ivec2 cell0, ivec2 size, int level, out ivec2 block, out ivec2 first,
                   out ivec2 end) {
  ivec2 wrapped = wrapTexel(cell0, size);
  ivec2 levelSize = max(size >> level, ivec2(1));
  block = min(wrapped >> level, levelSize - 1);
  first = cell0 - wrapped + (block << level);
  end = cell0 - wrapped + ivec2(block.x == levelSize.x - 1 ? size.x : (block.x + 1) << level,
                                block.y == levelSize.y - 1 ? size.y : (block.y + 1) << level);
  return texelFetch(uHeightPyramid, block, level).r;
}

// The four level-0 texels at the corners of cell `cell`, in one gather (the sampler wraps):
// x = (i, j), y = (i + 1, j), z = (i, j + 1), w = (i + 1, j + 1). textureGather returns the
// 2x2 block bilinear filtering would use at the point between their centres, in the order
// (i, j+1), (i+1, j+1), (i+1, j), (i, j).
vec4 cellCorners(ivec2 cell, vec2 texels) {
  vec2 between = (vec2(cell) + 1.0) / texels;
#ifdef HEIGHT_IN_NORMAL_ALPHA
  vec4 g = textureGather(uNormalMap, between, 3);
#else
  vec4 g = textureGather(uHeightMap, between, 0);
#endif
  vec4 h = vec4(g.w, g.z, g.x, g.y);
  return uHeightIsDepth ? 1.0 - h : h;
}

// The smallest tau in [0, tauMax] where c2 tau^2 + c1 tau + c0 = 0, given c0 < 0; -1 if none.
float firstRoot(float c2, float c1, float c0, float tauMax) {
  float root = -1.0;
  if (abs(c2) < 1e-7) {
    if (c1 > 0.0) root = -c0 / c1;
  } else {
    float discriminant = c1 * c1 - 4.0 * c2 * c0;
    if (discriminant >= 0.0) {
      // The stable pair of roots (no cancellation between c1 and the square root).
      float q = -0.5 * (c1 + (c1 >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
      float r1 = q / c2;
      float r2 = abs(q) > 1e-12 ? c0 / q : -1.0;
      float lo = min(r1, r2), hi = max(r1, r2);
      root = lo >= 0.0 ? lo : hi;
    }
  }
  return (root >= 0.0 && root <= tauMax) ? root : -1.0;
}

// The first tau in [0, tauMax] at which the ray at cell coordinates start + dir * (t + tau) and
// height 1 - (t + tau) meets the bilinear patch of `cell`, whose corners are h (cellCorners):
// h = h00 + A a + B b + E a b over the cell, with a and b linear in tau, so a quadratic. 0 when
// the ray is already at or below the patch, -1 when it stays above it.
float patchHit(ivec2 cell, vec4 h, vec2 start, vec2 dir, float t, float tauMax) {
  vec2 local = start + dir * t - vec2(cell);
  float A = h.y - h.x, B = h.z - h.x, E = h.x - h.y - h.z + h.w;
  float c0 = h.x + A * local.x + B * local.y + E * local.x * local.y - (1.0 - t);
  if (c0 >= -1e-6)
    return 0.0;
  float c1 = A * dir.x + B * dir.y + E * (local.x * dir.y + dir.x * local.y) + 1.0;
  float c2 = E * dir.x * dir.y;
  return firstRoot(c2, c1, c0, tauMax);
}

// The eye ray through the slab in cell coordinates: at depth t = 1 - h it is at
// start + dir * t (uv(t) = topUv - uvPerHeight t). Whole repeats of the map are taken out of
// its start so the walk's coordinates stay small (float precision).
struct CellRay {
  vec2 start;
  vec2 dir;
  vec2 inverseDir;  // 0 on an axis the ray never crosses a cell edge along
  bvec2 still;
  float nudge;      // t a step past an edge, so the next lookup lands beyond it (1e-4 texel)
  vec2 repeat;
  ivec2 size;
};

CellRay cellRay(vec2 uv, vec3 V, float scale, float bias) {
  float vz = max(V.z, 1e-4);
  vec2 uvPerHeight = scale * V.xy / vz;
  vec2 topUv = uv + (scale + bias) * V.xy / vz;
  CellRay ray;
  ray.repeat = floor(topUv);
  ray.size = ivec2(uHeightMapSize);
  vec2 texels = vec2(ray.size);
  ray.start = vec2(topUv.x - ray.repeat.x, 1.0 - (topUv.y - ray.repeat.y)) * texels - 0.5;
  ray.dir = vec2(-uvPerHeight.x, uvPerHeight.y) * texels;
  ray.still = lessThan(abs(ray.dir), vec2(1e-9));
  ray.inverseDir = vec2(ray.still.x ? 0.0 : 1.0 / ray.dir.x, ray.still.y ? 0.0 : 1.0 / ray.dir.y);
  ray.nudge = 1e-4 / max(max(abs(ray.dir.x), abs(ray.dir.y)), 1e-4);
  return ray;
}

// The t at which the ray, at t now, leaves the cells [first, end) (never behind t, whatever the
// rounding at the edge it just crossed; at most 1); `acrossX` says by which edge.
float exitFrom(CellRay ray, ivec2 first, ivec2 end, float t, out bool acrossX) {
  vec2 edge = vec2(ray.dir.x >= 0.0 ? float(end.x) : float(first.x),
                   ray.dir.y >= 0.0 ? float(end.y) : float(first.y));
  vec2 tEdge = vec2(ray.still.x ? 2.0 : (edge.x - ray.start.x) * ray.inverseDir.x,
                    ray.still.y ? 2.0 : (edge.y - ray.start.y) * ray.inverseDir.y);
  acrossX = tEdge.x <= tEdge.y;
  return clamp(min(tEdge.x, tEdge.y), t, 1.0);
}

// The visible point at depth t (the bottom of the slab if the walk ended below it).
ParallaxResult cellRayResult(CellRay ray, float t, int fetches) {
  t = min(t, 1.0);
  vec2 c = ray.start + ray.dir * t + 0.5;
  vec2 texels = vec2(ray.size);
  ParallaxResult result;
  result.uv = vec2(c.x / texels.x, 1.0 - c.y / texels.y) + ray.repeat;
  result.height = 1.0 - t;
  result.samples = fetches;
  return result;
}

// Where the map is minified, the exact tracers stop at the first block of pyramid level `level`
// whose maximum the ray reaches (at parameter t). Every other technique there sees the filtered
// map, which lies at or below that maximum; taking the block's top as the hit put the visible
// point ahead of that surface, often over the low mortar in front of a brick, whose self-shadow
// ray then met the brick: far mortar lines showed dotted shadows that no march showed. So from
// the block's top the ray marches the filtered map, read at the pixel's own mip level, in steps
// of one level-`level` texel (at most kMinifiedSteps, as POM does with its layers) and meets it
// where the last two samples' line crosses it (reference 001). Measured on the bricks sample at
// 720x540 on llvmpipe: 8 steps doubled the exact tracers' frame time, 2 left a quarter of the
// shadow difference to POM, 4 cost about half again (docs/techniques.md).
const int kMinifiedSteps = 4;

ParallaxResult filteredHitFrom(CellRay ray, float t, int level, float mipLevel, int fetches) {
  float path = max(max(abs(ray.dir.x), abs(ray.dir.y)), 1e-4);  // level-0 texels per unit t
  float dt = min(exp2(float(level)) / path, (1.0 - t) / float(kMinifiedSteps));
  ParallaxResult here = cellRayResult(ray, t, fetches);
  // The ray's height above the filtered map.
  float gap = here.height - sampleHeightAtLevel(here.uv, mipLevel);
  ++fetches;
  if (gap <= 0.0 || dt <= 0.0) {
    here.samples = fetches;
    return here;
  }
  for (int i = 0; i < kMinifiedSteps; ++i) {
    float nextT = min(t + dt, 1.0);
    ParallaxResult next = cellRayResult(ray, nextT, 0);
    float nextGap = next.height - sampleHeightAtLevel(next.uv, mipLevel);
    ++fetches;
    if (nextGap <= 0.0)
      return cellRayResult(ray, mix(t, nextT, gap / max(gap - nextGap, 1e-6)), fetches);
    t = nextT;
    gap = nextGap;
  }
  return cellRayResult(ray, t, fetches);  // not met within the steps: where the march stopped
}
