// Hex-tiling against visible repetition (Mikkelsen 2022, "Practical Real-Time Hex-Tiling",
// JCGT 11(3), after Heitz and Neyret 2018): the plane is covered with hexagons, each showing the
// map at its own random offset, and every point blends the three hexagons around it. The
// weights are the point's barycentric coordinates in the triangle of their centres, raised to a
// high power (the paper's 7) so that most of a hexagon shows one copy and the blend is a thin
// border, times a content term that lets the taller texel win there (the paper weighs colour by
// luminance and normals by slope; here every map takes the height's term, so the colour, normal
// and height of a point come from the same blend and the relief, its shading and its parallax
// stay aligned). No rotation: maps with light or a direction baked in (most photographs) would
// show it turned.
//
// Cost: three map reads where one was; the height's three feed every weight, so each surface
// map costs three reads more and every step of a parallax march three reads instead of one.
// Not with the exact tracers (cone, quadtree) or displacement, whose cone map, max-mip pyramid
// and tessellation describe the map as it is (the renderer does not define HEX_TILING then).

const float kHexCellsPerUv = 3.46410162;  // 2 sqrt(3): about three hexagons across a repeat
const float kHexSharpness = 7.0;          // the barycentric weights' exponent
const float kHexContent = 0.6;            // how much the height decides the border

struct HexTaps {
  vec2 uv[3];
  vec3 heights;  // the height of each tap
  vec3 weight;   // normalised
};

// A stable pseudo-random offset per hexagon (an integer hash: the same on every GPU).
vec2 hexOffset(ivec2 cell) {
  uint n = uint(cell.x) * 1597334677u ^ uint(cell.y) * 3812015801u;
  n = (n ^ (n >> 15)) * 2246822519u;
  n ^= n >> 13;
  return vec2(float(n & 0xffffu), float(n >> 16)) / 65536.0;
}

// The three hexagon centres around `uv` and the point's barycentric weights towards them.
void hexNeighbours(vec2 uv, out ivec2 cells[3], out vec3 barycentric) {
  vec2 st = uv * kHexCellsPerUv;
  // Skewed so that the centres of a hexagonal tiling land on integer points: each unit square
  // of the skewed grid is two triangles of centres.
  vec2 skewed = vec2(st.x - 0.57735027 * st.y, 1.15470054 * st.y);
  ivec2 base = ivec2(floor(skewed));
  vec2 f = fract(skewed);
  float rest = 1.0 - f.x - f.y;
  if (rest > 0.0) {
    cells[0] = base;
    cells[1] = base + ivec2(0, 1);
    cells[2] = base + ivec2(1, 0);
    barycentric = vec3(rest, f.y, f.x);
  } else {
    cells[0] = base + ivec2(1, 1);
    cells[1] = base + ivec2(1, 0);
    cells[2] = base + ivec2(0, 1);
    barycentric = vec3(-rest, 1.0 - f.y, 1.0 - f.x);
  }
}

vec3 hexWeights(vec3 barycentric, vec3 heights) {
  vec3 w = mix(vec3(1.0), heights, kHexContent) * pow(barycentric, vec3(kHexSharpness));
  return w / max(w.x + w.y + w.z, 1e-20);
}

// The three taps' coordinates around `uv`, and the point's barycentric weights.
HexTaps hexTapPlaces(vec2 uv, out vec3 barycentric) {
  ivec2 cells[3];
  hexNeighbours(uv, cells, barycentric);
  HexTaps taps;
  for (int i = 0; i < 3; ++i) taps.uv[i] = uv + hexOffset(cells[i]);
  return taps;
}

HexTaps hexTaps(vec2 uv, vec2 dx, vec2 dy) {
  vec3 barycentric;
  HexTaps taps = hexTapPlaces(uv, barycentric);
  for (int i = 0; i < 3; ++i)
    taps.heights[i] = heightFromTexel(sampleMap(HEIGHT_SOURCE_MAP, taps.uv[i], dx, dy));
  taps.weight = hexWeights(barycentric, taps.heights);
  return taps;
}

HexTaps hexTapsAtLevel(vec2 uv, float level) {
  vec3 barycentric;
  HexTaps taps = hexTapPlaces(uv, barycentric);
  for (int i = 0; i < 3; ++i)
    taps.heights[i] =
        heightFromTexel(textureLod(HEIGHT_SOURCE_MAP, mapCoordinates(taps.uv[i]), level));
  taps.weight = hexWeights(barycentric, taps.heights);
  return taps;
}

vec4 sampleMapHex(sampler2D map, HexTaps taps, vec2 dx, vec2 dy) {
  return taps.weight.x * sampleMap(map, taps.uv[0], dx, dy) +
         taps.weight.y * sampleMap(map, taps.uv[1], dx, dy) +
         taps.weight.z * sampleMap(map, taps.uv[2], dx, dy);
}
