// The cone technique: the exact first intersection of the eye ray with the bilinear height
// field, reached by cone steps through the empty space above it (cone step mapping, Dummer
// 2006; GPU Gems 3 ch. 18), with the cone map of core/tracing/ConeMap.h, whose cones hold no
// point of the bilinear surface (not only its texels: Bán, Valasek et al., EGSR 2024).
//
// At a point p of cell c, at height z over the surface f(p), the cone of ratio w allows a step
// of dt = (z - f(p)) w / (s + w) in depth, s being the ray's texels per unit of depth. Cone steps
// alone approach the surface without reaching it, so each step is at least the cell's own
// (the 2024 paper's minimum step): a ray above the cell's highest corner goes to where it
// leaves the cell or falls to that corner's height, whichever is first. At or below it, the
// cell's bilinear patch is intersected exactly (bilinear_cell.glsl); no step ever passes the
// surface, so no refinement is needed and one-texel walls are never stepped over.
// Where the height map is minified (read at mip level L > 0) the walk treats the pyramid's
// level-L blocks as its cells and, from the first block top it reaches, meets the filtered map
// the other techniques read there, as the quadtree does (filteredHitFrom, bilinear_cell.glsl);
// the exact hit would alias, jumping between the texels a pixel covers as the view moves.
// Magnified, it is exact.

uniform sampler2D uConeMap;  // R32F, one cone ratio per cell (texels per unit height), nearest

// Enough for a 16k map seen at a grazing angle; a ray still walking after it stops where it is.
const int kConeIterationCap = 512;
// The cones bound the float texels; a height read from a 16-bit texture (the normal map's alpha)
// is up to half a step off at p and at the point met, so each cone step keeps this much above.
const float kConeMargin = 1.0 / 65535.0;

ParallaxResult traceCones(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale, float bias,
                          float mipLevel) {
  CellRay ray = cellRay(uv, V, scale, bias);
  vec2 texels = vec2(ray.size);
  float speed = length(ray.dir);  // texels per unit of depth
  int finest = clamp(int(floor(mipLevel)), 0, uHeightPyramidLevels - 1);
  float t = 0.0;
  int fetches = 0;
  for (int i = 0; i < kConeIterationCap && t < 1.0; ++i) {
    vec2 c = ray.start + ray.dir * t;
    ivec2 cell = ivec2(floor(c));
    vec4 corners = cellCorners(cell, texels);
    fetches += 4;  // one gather, four texels
    bool acrossX;
    float tExit, highest;
    if (finest > 0) {  // minified: the level's block stands for the cell
      ivec2 block, first, end;
      highest = pyramidBlock(cell, ray.size, finest, block, first, end);
      ++fetches;
      tExit = exitFrom(ray, first, end, t, acrossX);
    } else {
      tExit = exitFrom(ray, cell, cell + 1, t, acrossX);
      highest = max(max(corners.x, corners.y), max(corners.z, corners.w));
    }
    float z = 1.0 - t;
    if (z > highest) {
      vec2 local = c - vec2(cell);
      float f = mix(mix(corners.x, corners.y, local.x), mix(corners.z, corners.w, local.x), local.y);
      float ratio = texelFetch(uConeMap, wrapTexel(cell, ray.size), 0).r;
      ++fetches;
      float coneStep = max(z - f - kConeMargin, 0.0) * ratio / (speed + ratio);
      // Within the cell (or block) the ray stays above its highest point until it leaves it or
      // falls to that height; leaving, it goes a nudge into the next one.
      float cellStep = 1.0 - highest < tExit ? 1.0 - highest - t : tExit + ray.nudge - t;
      t += max(coneStep, cellStep);
      continue;
    }
    if (finest > 0)  // from the block's top to the filtered map (bilinear_cell.glsl)
      return filteredHitFrom(ray, max(t, 1.0 - highest), finest, mipLevel, fetches);
    float tau = patchHit(cell, corners, ray.start, ray.dir, t, tExit - t);
    if (tau >= 0.0) {
      t += tau;
      break;
    }
    t = tExit + ray.nudge;
  }
  // Not found: the ray reached the bottom of the slab (t = 1, where every height >= 0 is met),
  // or the iteration cap stopped it, which leaves the point it had reached.
  return cellRayResult(ray, t, fetches);
}
