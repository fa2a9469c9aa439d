// The quadtree technique: the exact first intersection of the eye ray with the bilinear height
// field, found by walking the maximum-mipmap pyramid (Tevs, Ihrke and Seidel, I3D 2008; the
// pyramid is core/tracing/MaxMipPyramid.h). A block whose maximum the ray passes above is skipped
// whole and the walk climbs a level; where the ray reaches a block's maximum it descends; at
// level 0 it intersects the cell's bilinear patch exactly (a quadratic along the ray).
// Coordinates are texture texel units with rows top first, as the maps are stored
// (material_inputs.glsl); cells lie between texel centres.
//
// Where the height map is minified (read at mip level L > 0) the walk stops descending at level
// L and takes the block's top as the hit: within a pixel's footprint of the exact point, as the
// other techniques are there (they read the map's mip L). Magnified, it is exact.
// The walk starts at the level whose blocks are as long as the ray's path, not at the 1x1 top.

uniform sampler2D uHeightPyramid;  // R32F, one level per pyramid level, nearest
uniform int uHeightPyramidLevels;

// Enough for a 16k map seen at a grazing angle; a ray still walking after it stops where it is.
const int kQuadtreeIterationCap = 512;

// Wraps a texel index within one repeat either side of the map (the walk starts inside it and
// never travels a whole map further); GLSL's % is undefined for negative operands.
ivec2 wrapTexel(ivec2 texel, ivec2 size) {
  ivec2 wrapped = texel + size * ivec2(lessThan(texel, ivec2(0)));
  return wrapped - size * ivec2(greaterThanEqual(wrapped, size));
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

ParallaxResult traceQuadtree(vec2 uv, vec3 V, float scale, float bias, float mipLevel) {
  float vz = max(V.z, 1e-4);
  vec2 uvPerHeight = scale * V.xy / vz;
  vec2 topUv = uv + (scale + bias) * V.xy / vz;
  // Whole repeats are taken out so the walk's coordinates stay small (float precision).
  vec2 repeat = floor(topUv);
  ivec2 size = ivec2(uHeightMapSize);
  vec2 texels = vec2(size);
  // The ray at depth t = 1 - h: cell coordinates start + dir * t (uv(t) = topUv - uvPerHeight t).
  vec2 start = vec2(topUv.x - repeat.x, 1.0 - (topUv.y - repeat.y)) * texels - 0.5;
  vec2 dir = vec2(-uvPerHeight.x, uvPerHeight.y) * texels;
  bvec2 still = lessThan(abs(dir), vec2(1e-9));  // never crosses a cell edge on this axis
  vec2 inverseDir = vec2(still.x ? 0.0 : 1.0 / dir.x, still.y ? 0.0 : 1.0 / dir.y);
  ivec2 stepDir = ivec2(dir.x >= 0.0 ? 1 : -1, dir.y >= 0.0 ? 1 : -1);
  // Past a block's edge by this much in t (1e-4 texel), so the next lookup lands beyond it.
  float nudge = 1e-4 / max(max(abs(dir.x), abs(dir.y)), 1e-4);

  int top = uHeightPyramidLevels - 1;
  int finest = clamp(int(floor(mipLevel)), 0, top);
  float path = max(abs(dir.x), abs(dir.y));  // cells crossed from the top to the bottom
  int level = clamp(int(ceil(log2(path + 1.0))), finest, top);
  float t = 0.0;
  int fetches = 0;
  bool found = false;
  for (int i = 0; i < kQuadtreeIterationCap && t < 1.0; ++i) {
    vec2 c = start + dir * t;
    ivec2 cell0 = ivec2(floor(c));  // level-0 cell, not wrapped
    ivec2 wrapped = wrapTexel(cell0, size);
    ivec2 levelSize = max(size >> level, ivec2(1));
    ivec2 cell = min(wrapped >> level, levelSize - 1);
    float bound = texelFetch(uHeightPyramid, cell, level).r;
    ++fetches;
    // The block in unwrapped level-0 cells: [first, end); the last block runs to the map's edge.
    ivec2 first = cell0 - wrapped + (cell << level);
    ivec2 end = cell0 - wrapped + ivec2(cell.x == levelSize.x - 1 ? size.x : (cell.x + 1) << level,
                                        cell.y == levelSize.y - 1 ? size.y : (cell.y + 1) << level);
    vec2 edge = vec2(dir.x >= 0.0 ? float(end.x) : float(first.x),
                     dir.y >= 0.0 ? float(end.y) : float(first.y));
    vec2 tEdge = vec2(still.x ? 2.0 : (edge.x - start.x) * inverseDir.x,
                      still.y ? 2.0 : (edge.y - start.y) * inverseDir.y);
    // Never behind the ray's current point, whatever the rounding at the edge it just crossed.
    float tExit = clamp(min(tEdge.x, tEdge.y), t, 1.0);
    float tBound = 1.0 - bound;  // the ray's height falls to the block's maximum here
    if (tBound >= tExit) {  // over the whole block: skip it, and climb if it left the parent
      t = tExit + nudge;
      // The block it enters is the neighbour across the edge it left by (wrapping): another
      // parent unless the two share one. Only the walk's speed depends on this choice; every
      // block is looked up afresh from t.
      bool acrossX = tEdge.x <= tEdge.y;
      int index = acrossX ? cell.x : cell.y;
      int count = acrossX ? levelSize.x : levelSize.y;
      int neighbour = index + (acrossX ? stepDir.x : stepDir.y);
      neighbour = neighbour < 0 ? count - 1 : (neighbour >= count ? 0 : neighbour);
      int parents = max(count >> 1, 1);
      if (min(index >> 1, parents - 1) != min(neighbour >> 1, parents - 1))
        level = min(level + 1, top);
      continue;
    }
    t = max(t, tBound);
    if (level > finest) {
      --level;
      continue;
    }
    if (finest > 0) {  // minified: the block's top, within the pixel's footprint
      found = true;
      break;
    }
    // Level 0: the bilinear patch h = h00 + A a + B b + E a b over the cell, a and b linear in
    // tau = t' - t; solve h(tau) = 1 - (t + tau).
    vec4 corners = cellCorners(cell0, texels);
    float h00 = corners.x, h10 = corners.y, h01 = corners.z, h11 = corners.w;
    fetches += 4;  // one gather, four texels
    vec2 local = start + dir * t - vec2(cell0);
    float A = h10 - h00, B = h01 - h00, E = h00 - h10 - h01 + h11;
    float c0 = h00 + A * local.x + B * local.y + E * local.x * local.y - (1.0 - t);
    if (c0 >= -1e-6) {  // already at or below the surface where it entered
      found = true;
      break;
    }
    float c1 = A * dir.x + B * dir.y + E * (local.x * dir.y + dir.x * local.y) + 1.0;
    float c2 = E * dir.x * dir.y;
    float tau = firstRoot(c2, c1, c0, tExit - t);
    if (tau >= 0.0) {
      t += tau;
      found = true;
      break;
    }
    t = tExit + nudge;  // the next cell, at level 0 still; blocks skipped there climb
  }
  // Not found: the ray reached the bottom of the slab (t = 1, where every height >= 0 is met),
  // or the iteration cap stopped it, which leaves the point it had reached.
  t = found ? t : min(t, 1.0);
  vec2 c = start + dir * t + 0.5;
  ParallaxResult result;
  result.uv = vec2(c.x / texels.x, 1.0 - c.y / texels.y) + repeat;
  result.height = 1.0 - t;
  result.samples = fetches;
  return result;
}
