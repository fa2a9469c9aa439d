// Material fragment stage. Builds the tangent frame, moves view and light into tangent space
// (reference 004: Vt = (T.V, B.V, N.V)), finds the visible point with the compiled parallax
// technique, shadows it from the height field and shades it with Blinn-Phong, or writes one of
// the debug views. With the displacement technique the tessellation stages (material.tesc,
// material.tese) have already moved the geometry, and the fragment is the visible point.

#include "include/material_inputs.glsl"
#include "include/debug_views.glsl"
#include "include/tangent_space.glsl"
#include "include/height.glsl"
#include "include/displaced_position.glsl"
#include "include/parallax.glsl"
#ifdef ENGINE_PREVIEW
#include "include/engine_parallax.glsl"
#endif
#include "include/self_shadow.glsl"
#include "include/normal_mapping.glsl"
#include "include/lighting.glsl"
#include "include/pbr.glsl"
#include "include/display.glsl"
#include "include/heatmap.glsl"
#include "include/color.glsl"

in VertexData {
  vec3 worldPosition;
  vec2 uv;
  vec3 worldNormal;
  vec4 worldTangent;
  vec2 uvScale;  // world units per unit of u and of v (core::Vertex::uvScale)
} vIn;

out vec4 fragColor;

// Data views either write raw values (FLOAT_OUTPUT, for EXR and the error view) or a display
// colour.
vec4 dataOutput(vec3 raw, vec3 display) {
#ifdef FLOAT_OUTPUT
  return vec4(raw, 1.0);
#else
  return vec4(display, 1.0);
#endif
}

void main() {
#ifdef TECHNIQUE_DISPLACEMENT
  // A displaced surface can show the back of a fold (a wall turned away from the eye) where
  // the mesh itself faces the eye: the mesh's side decides how the frame faces, not the
  // displaced triangle's.
  bool facesEye = dot(vIn.worldNormal, uCameraPosition - vIn.worldPosition) >= 0.0;
#else
  bool facesEye = gl_FrontFacing;
#endif
  TangentFrame frame = buildTangentFrame(vIn.worldNormal, vIn.worldTangent, facesEye);
  vec3 V = normalize(toTangentSpace(frame, normalize(uCameraPosition - vIn.worldPosition)));
  vec3 L = toTangentSpace(frame, uLightDirection);
  vec2 entryUv = vIn.uv * uTiling;
  // Gradients once, outside every loop (reference 001: SampleGrad/textureGrad).
  vec2 dx = dFdx(entryUv);
  vec2 dy = dFdy(entryUv);
  UvToWorld uvFrame = uvToWorld(vIn.worldPosition, entryUv);
  // Eye and light in the marches' (u, v, height) space: one depth in world units everywhere.
  float heightToWorld = uWorldPerUv / uTiling;
  vec2 uvScale = vIn.uvScale / uTiling;
  vec3 eyeUvHeight = toUvHeightSpace(V, uvScale, heightToWorld);
  vec3 marchV = normalize(eyeUvHeight);
  vec3 marchL = normalize(toUvHeightSpace(L, uvScale, heightToWorld));
#ifdef CURVED_SILHOUETTES
  vec3 worldForm = secondFundamentalForm(frame.normal, entryUv, uvFrame);
  gCurvedRay = curvedRayOf(worldForm, eyeUvHeight, heightToWorld);
  // Curved meshes are taken as closed: where a ray leaves the front surface, the inside of the
  // back (drawn too, for open meshes) must not fill the gap. Flat parts keep both sides.
  if (!facesEye && dot(abs(worldForm), vec3(1.0)) > 1e-3 * max(heightToWorld, 1e-6)) discard;
#endif

#if DEBUG_VIEW == VIEW_RAY
#ifdef ENGINE_PREVIEW
  fragColor = vec4(entryUv, V.xy);  // an engine marches along the tangent frame's view
#else
  fragColor = vec4(entryUv, marchV.xy);
#endif
  return;
#endif

  float mipLevel = heightMipLevel(entryUv);
#ifdef ENGINE_PREVIEW
  // The engine's own trace, fade and all (engine_parallax.glsl); Relief's fade is not the
  // engine's. Scale and bias stay Relief's: the export's conversions make them the same relief.
  // Engines march along the tangent frame's view and light, as the shading uses them.
  float scale = uHeightScale;
  float bias = uHeightBias;
  ParallaxResult visible = engineVisiblePoint(entryUv, V, dx, dy);
  marchL = L;
#else
  // Fade the relief out where the height map is read at a coarse mip level.
  float fade = uLodFade > 0.0 ? 1.0 - smoothstep(uLodFade - 1.0, uLodFade, mipLevel) : 1.0;
  float scale = uHeightScale * fade;
  float bias = uHeightBias * fade;

  ParallaxResult visible;
  if (fade > 0.0) {
    visible = findVisiblePoint(entryUv, marchV, dx, dy, scale, bias, mipLevel);
  } else {
    visible.uv = entryUv;
    visible.height = sampleHeight(entryUv, dx, dy);
    visible.samples = 1;
  }
#endif

#ifdef CURVED_SILHOUETTES
  if (gMissedSurface) discard;  // curved_march.glsl: outside the relief's outline
#endif
#ifdef UV_EDGE_CLAMP
  vec2 meshUv = visible.uv / uTiling;
  if (any(lessThan(meshUv, vec2(0.0))) || any(greaterThan(meshUv, vec2(1.0)))) discard;
#endif

  int samples = visible.samples;
  float shadow =
      selfShadow(visible.uv, visible.height, marchL, dx, dy, scale, mipLevel, samples);

#ifdef TECHNIQUE_DISPLACEMENT
  vec3 displaced = vIn.worldPosition;  // the tessellation stage moved the geometry there
#else
  float surfaceHeight = visible.height * scale + bias;  // UV units above the mesh surface
  vec3 displaced = displacedWorldPosition(uvFrame, vIn.worldPosition, visible.uv - entryUv,
                                          surfaceHeight, frame.normal, heightToWorld);
#endif
#ifdef DEPTH_OFFSET
  vec4 clip = uViewProjection * vec4(displaced, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
#endif

  SurfaceSample surface;
#ifdef HEX_TILING
  // Every surface map through the same hexagons and weights as the height (hex_tiling.glsl).
  HexTaps taps = hexTaps(visible.uv, dx, dy);
#define SURFACE_MAP(map) sampleMapHex(map, taps, dx, dy)
  surface.normal = sampleNormalMapHex(taps, dx, dy);
#else
#define SURFACE_MAP(map) sampleMap(map, visible.uv, dx, dy)
  surface.normal = sampleNormalMap(visible.uv, dx, dy);
#endif
  surface.albedo = SURFACE_MAP(uColorMap).rgb;  // sRGB texture: linear
  surface.occlusion = uHasOcclusionMap ? SURFACE_MAP(uOcclusionMap).r : 1.0;
  surface.roughness = uHasRoughnessMap ? SURFACE_MAP(uRoughnessMap).r : 0.0;
#ifdef SHADING_PBR
  surface.metallic = uHasMetallicMap ? SURFACE_MAP(uMetallicMap).r : 1.0;
#else
  surface.metallic = 0.0;
#endif

#if DEBUG_VIEW == VIEW_SHADING
#ifdef SHADING_PBR
  vec3 radiance = shadePbr(surface, L, V, shadow, frame);
#else
  vec3 radiance = shadeBlinnPhong(surface, L, V, shadow);
#endif
  // Float output: the linear radiance, unclamped (what --format exr measures), before the
  // display transform.
  fragColor = dataOutput(radiance, linearToSrgb(displayTransform(radiance)));
#elif DEBUG_VIEW == VIEW_HEIGHT
  fragColor = dataOutput(vec3(visible.height), vec3(visible.height));
#elif DEBUG_VIEW == VIEW_NORMAL
  fragColor = vec4(surface.normal * 0.5 + 0.5, 1.0);
#elif DEBUG_VIEW == VIEW_UV
  // Float output carries the height map's mip level in b: the error view leaves out the pixels
  // where the map is minified (core/tracing/UvErrorMap.h).
  fragColor = dataOutput(vec3(visible.uv, mipLevel), vec3(fract(visible.uv), 0.0));
#elif DEBUG_VIEW == VIEW_OFFSET
  vec2 offsetTexels = (visible.uv - entryUv) * uHeightMapSize;
  fragColor = dataOutput(vec3(offsetTexels, 0.0),
                         vec3(0.5 + 0.5 * offsetTexels / kOffsetDisplayTexels, 0.5));
#elif DEBUG_VIEW == VIEW_STEPS
  float most = float(max(uMaxSamples, uMinSamples) + 1 + uRefinementSteps + uShadowSamples);
  fragColor = dataOutput(vec3(float(samples)), heatmapColor(float(samples) / most));
#elif DEBUG_VIEW == VIEW_SHADOW
  fragColor = dataOutput(vec3(1.0 - shadow), vec3(1.0 - shadow));
#elif DEBUG_VIEW == VIEW_TANGENTS
  fragColor = vec4(frame.tangent * 0.5 + 0.5, 1.0);
#elif DEBUG_VIEW == VIEW_MIP
  fragColor = dataOutput(vec3(mipLevel), heatmapColor(mipLevel / kMipDisplayLevels));
#elif DEBUG_VIEW == VIEW_DEPTH
  // The depth the depth buffer receives: of the displaced surface when it is written
  // (depthOffset), of the mesh surface otherwise.
#ifdef DEPTH_OFFSET
  float distanceToEye = length(displaced - uCameraPosition);
#else
  float distanceToEye = length(vIn.worldPosition - uCameraPosition);
#endif
  float shade = 1.0 - clamp((distanceToEye - uDepthDisplayRange.x) /
                            max(uDepthDisplayRange.y - uDepthDisplayRange.x, 1e-6), 0.0, 1.0);
  fragColor = dataOutput(vec3(distanceToEye), vec3(shade));
#endif

#ifndef FLOAT_OUTPUT
  // The tile preview's seam lines (renderer/FrameSettings.h): where the map's edges meet on the
  // mesh surface, about one and a half pixels wide at any distance, amber over any view.
  if (uTileSeams) {
    vec2 pixelsToEdge = abs(fract(entryUv + 0.5) - 0.5) / max(fwidth(entryUv), vec2(1e-6));
    float line = 1.0 - smoothstep(0.75, 1.5, min(pixelsToEdge.x, pixelsToEdge.y));
    fragColor.rgb = mix(fragColor.rgb, vec3(1.0, 0.72, 0.1), 0.85 * line);
  }
#endif
}
