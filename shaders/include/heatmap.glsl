// Heat-map colours for the cost, mip and error views. Mirrors core/Heatmap.cpp (the same five
// control points); keep the two in step. Output is a display (sRGB) colour.

vec3 heatmapColor(float t) {
  const vec3 stops[5] = vec3[5](vec3(0.05, 0.05, 0.35), vec3(0.00, 0.45, 0.85),
                                vec3(0.10, 0.75, 0.35), vec3(0.95, 0.80, 0.10),
                                vec3(0.85, 0.10, 0.05));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int index = min(int(x), 3);
  return mix(stops[index], stops[index + 1], x - float(index));
}
