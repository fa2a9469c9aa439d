// The quadtree technique: the exact first intersection of the eye ray with the bilinear height
// field, found by walking the maximum-mipmap pyramid (Tevs, Ihrke and Seidel, I3D 2008; the
// pyramid is core/tracing/MaxMipPyramid.h). A block whose maximum the ray passes above is skipped
// whole and the walk climbs a level; where the ray reaches a block's maximum it descends; at
// level 0 it intersects the cell's bilinear patch exactly (a quadratic along the ray).
// Coordinates are texture texel units with rows top first, as the maps are stored
// (material_inputs.glsl); cells lie between texel centres (bilinear_cell.glsl).
//
// Where the height map is minified (read at mip level L > 0) the walk stops descending at level
// L and, from the first block's top it reaches, meets the filtered map the other techniques
// read there (filteredHitFrom, bilinear_cell.glsl). Magnified, it is exact.
// The walk starts at the level whose blocks are as long as the ray's path, not at the 1x1 top.

// Enough for a 16k map seen at a grazing angle; a ray still walking after it stops where it is.
const int kQuadtreeIterationCap = 512;

ParallaxResult traceQuadtree(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale, float bias,
                             float mipLevel) {
  CellRay ray = cellRay(uv, V, scale, bias);
  ivec2 size = ray.size;
  vec2 texels = vec2(size);
  ivec2 stepDir = ivec2(ray.dir.x >= 0.0 ? 1 : -1, ray.dir.y >= 0.0 ? 1 : -1);

  int top = uHeightPyramidLevels - 1;
  int finest = clamp(int(floor(mipLevel)), 0, top);
  float path = max(abs(ray.dir.x), abs(ray.dir.y));  // cells crossed from the top to the bottom
  int level = clamp(int(ceil(log2(path + 1.0))), finest, top);
  float t = 0.0;
  int fetches = 0;
  for (int i = 0; i < kQuadtreeIterationCap && t < 1.0; ++i) {
    vec2 c = ray.start + ray.dir * t;
    ivec2 cell0 = ivec2(floor(c));  // level-0 cell, not wrapped
    ivec2 cell, first, end;
    float bound = pyramidBlock(cell0, size, level, cell, first, end);
    ++fetches;
    ivec2 levelSize = max(size >> level, ivec2(1));
    bool acrossX;
    float tExit = exitFrom(ray, first, end, t, acrossX);
    float tBound = 1.0 - bound;  // the ray's height falls to the block's maximum here
    if (tBound >= tExit) {  // over the whole block: skip it, and climb if it left the parent
      t = tExit + ray.nudge;
      // The block it enters is the neighbour across the edge it left by (wrapping): another
      // parent unless the two share one. Only the walk's speed depends on this choice; every
      // block is looked up afresh from t.
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
    if (finest > 0)  // minified: from the block's top to the filtered map
      return filteredHitFrom(ray, t, finest, mipLevel, fetches);
    // Level 0: the cell's bilinear patch, exactly.
    vec4 corners = cellCorners(cell0, texels);
    fetches += 4;  // one gather, four texels
    float tau = patchHit(cell0, corners, ray.start, ray.dir, t, tExit - t);
    if (tau >= 0.0) {
      t += tau;
      break;
    }
    t = tExit + ray.nudge;  // the next cell, at level 0 still; blocks skipped there climb
  }
  // Not found: the ray reached the bottom of the slab (t = 1, where every height >= 0 is met),
  // or the iteration cap stopped it, which leaves the point it had reached.
  return cellRayResult(ray, t, fetches);
}
