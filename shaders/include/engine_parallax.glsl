// The engine preview modes: each engine's own relief tracer, written from the engine's public
// shader source (cited per function), in Relief's terms: uv the tiled entry UV, V the unit
// tangent-space direction toward the eye, h = sampleHeight() with 1 the top. The engines'
// parameters arrive converted by core/exporters/EnginePreview.cpp from the values the engine
// exports write, so the preview traces the exported material:
//   uEngineDepth           full relief depth in tiled texture widths (URP: its amplitude)
//   uEngineMinSteps/Max    the engine's head-on and grazing sample counts
//   uEngineReferencePlane  Unreal's Reference Plane (the height on the mesh, 1 the top)
//   uEngineLodThreshold    HDRP's _PPDLodThreshold
// None of the engines' materials shadows its relief; the preview compiles no self-shadowing.
// The heights are read as each engine reads them: Godot and URP with the fragment's own
// derivatives (implicit texture()), Unreal with the entry UV's (SampleGrad), HDRP at one
// explicit level (SampleLevel).

uniform float uEngineDepth;
uniform float uEngineMinSteps;
uniform float uEngineMaxSteps;
uniform float uEngineReferencePlane;
uniform float uEngineLodThreshold;

ParallaxResult engineResult(vec2 uv, vec2 dx, vec2 dy, int samples) {
  ParallaxResult result;
  result.uv = uv;
  result.height = sampleHeight(uv, dx, dy);
  result.samples = samples + 1;
  return result;
}

#if defined(ENGINE_GODOT_OFFSET) || defined(ENGINE_GODOT_DEEP)
// Godot 4 (4.0-4.3), scene/resources/material.cpp, BaseMaterial3D::_update_shader, "Height":
// depth = 1 - h, offsets along view_dir.xy * heightmap_scale * 0.01 with no division by view.z
// (offset limiting), the top of the relief on the surface (no bias).
ParallaxResult godotParallax(vec2 uv, vec3 V, vec2 dx, vec2 dy) {
#ifdef ENGINE_GODOT_OFFSET
  float depth = 1.0 - sampleHeight(uv, dx, dy);
  return engineResult(uv - V.xy * depth * uEngineDepth, dx, dy, 1);
#else
  // "Height Deep Parallax": a fractional layer count lerped by |view.z|, stepped until the
  // layer depth passes the map's depth, then one linear interpolation with the layer before.
  float numLayers = mix(uEngineMaxSteps, uEngineMinSteps, abs(V.z));
  float layerDepth = 1.0 / numLayers;
  vec2 delta = V.xy * uEngineDepth / numLayers;
  vec2 ofs = uv;
  float depth = 1.0 - sampleHeight(ofs, dx, dy);
  float currentDepth = 0.0;
  int samples = 1;
  // Godot's loop has no bound; depth <= 1 ends it after ceil(numLayers) steps. The bound here
  // only guards against a NaN depth.
  while (currentDepth < depth && samples <= 4096) {
    ofs -= delta;
    depth = 1.0 - sampleHeight(ofs, dx, dy);
    currentDepth += layerDepth;
    ++samples;
  }
  vec2 previousOfs = ofs + delta;
  float afterDepth = depth - currentDepth;
  float beforeDepth = (1.0 - sampleHeight(previousOfs, dx, dy)) - currentDepth + layerDepth;
  float weight = afterDepth / (afterDepth - beforeDepth);
  return engineResult(mix(ofs, previousOfs, weight), dx, dy, samples + 1);
#endif
}
#endif

#ifdef ENGINE_UNREAL_POM
// Unreal Engine 5, Epic's ParallaxOcclusionMapping material function
// (/Engine/Functions/Engine_MaterialFunctions01/Texturing). Epic ships it as a binary asset;
// its Custom node's HLSL is public, and the graph around it is read here from the HLSL that
// materials using it compile to (the preshader's step counts, the Local expressions around the
// Custom node). A dithered step count some materials add on top is left out. Its graph:
// UVDist = Height Ratio * -V.xy / V.z, the march starting (1 - Reference Plane) of it above the
// UVs, a step count lerp(Max Steps, Min Steps, saturate(|V.N|)) whose floor bounds the loop
// (+2) while its reciprocal is the step; its Custom node marches down from ray height 1 and, at
// the first sample above the ray, intersects the lines through the last two samples. Without a
// hit the ray runs past the bottom (MaxSteps + 2 steps) and stays there.
ParallaxResult unrealParallax(vec2 uv, vec3 V, vec2 dx, vec2 dy) {
  vec2 uvDist = uEngineDepth * (-V.xy / V.z);
  vec2 start = uv - uvDist * (1.0 - uEngineReferencePlane);
  float steps = mix(uEngineMaxSteps, uEngineMinSteps, clamp(abs(V.z), 0.0, 1.0));
  float stepSize = 1.0 / steps;
  vec2 stepUv = uvDist * stepSize;
  float rayHeight = 1.0;
  float oldRay = 1.0;
  vec2 offset = vec2(0.0);
  float oldTex = 1.0;
  int samples = 0;
  for (int i = 0; float(i) < floor(steps) + 2.0; ++i) {
    float texAtRay = sampleHeight(start + offset, dx, dy);
    ++samples;
    if (rayHeight < texAtRay) {
      float x = (texAtRay - rayHeight) / ((oldRay - oldTex) + (texAtRay - rayHeight));
      offset -= x * stepUv;
      break;
    }
    oldRay = rayHeight;
    rayHeight -= stepSize;
    offset += stepUv;
    oldTex = texAtRay;
  }
  return engineResult(start + offset, dx, dy, samples);
}
#endif

#ifdef ENGINE_URP_OFFSET
// Unity URP Lit, com.unity.render-pipelines.core ShaderLibrary/ParallaxMapping.hlsl (12.x-17.x):
// ParallaxOffset1Step: one read, (h * A - A / 2) * v.xy / (v.z + 0.42) with v the unit view:
// the middle of the relief on the surface, the offset limited by the 0.42.
ParallaxResult urpParallax(vec2 uv, vec3 V, vec2 dx, vec2 dy) {
  float amplitude = uEngineDepth;
  float height = sampleHeight(uv, dx, dy) * amplitude - amplitude / 2.0;
  vec3 v = normalize(V);
  v.z += 0.42;
  return engineResult(uv + height * (v.xy / v.z), dx, dy, 1);
}
#endif

#ifdef ENGINE_HDRP_POM
// Unity HDRP Lit (10.x-17.x): LitData.hlsl's ApplyPerPixelDisplacement and
// com.unity.render-pipelines.core ShaderLibrary/PerPixelDisplacement.hlsl's
// ParallaxOcclusionMapping.
float hdrpFastACosPos(float x) {  // Core's Common.hlsl FastACosPos (max error 1.3e-3 rad)
  x = abs(x);
  return ((0.0468878 * x - 0.203471) * x + 1.570796) * sqrt(1.0 - x);
}

ParallaxResult hdrpParallax(vec2 uv, vec3 V, vec2 dx, vec2 dy) {
  // ComputeTextureLOD of the UVs in texels: one level for every read.
  vec2 dxTexels = dx * uHeightMapSize;
  vec2 dyTexels = dy * uHeightMapSize;
  float lod = max(0.5 * log2(max(dot(dxTexels, dxTexels), dot(dyTexels, dyTexels))), 0.0);
  // The view in UV space (uvSpaceScale = the depth): its angle picks the step count.
  vec3 viewDirUv = normalize(vec3(V.xy * uEngineDepth, V.z));
  float unitAngle = clamp(hdrpFastACosPos(viewDirUv.z) * (2.0 / 3.14159265), 0.0, 1.0);
  int numSteps = int(mix(uEngineMinSteps, uEngineMaxSteps, unitAngle));

  float stepSize = 1.0 / float(numSteps);
  vec2 perStep = stepSize * (viewDirUv.xy / -viewDirUv.z);
  vec2 current = perStep;
  float previousHeight = sampleHeightAtLevel(uv, lod);
  float currentHeight = sampleHeightAtLevel(uv + current, lod);
  int samples = 2;
  float rayHeight = 1.0 - stepSize;
  for (int i = 0; i < numSteps; ++i) {
    if (currentHeight > rayHeight)
      break;
    previousHeight = currentHeight;
    rayHeight -= stepSize;
    current += perStep;
    currentHeight = sampleHeightAtLevel(uv + current, lod);
    ++samples;
  }
  // Secant refinement (POM_SECANT_METHOD, after Risser), at most three reads.
  float pt0 = rayHeight + stepSize;
  float pt1 = rayHeight;
  float delta0 = pt0 - previousHeight;
  float delta1 = pt1 - currentHeight;
  vec2 offset = vec2(0.0);
  for (int i = 0; i < 3; ++i) {
    float intersectionHeight = (pt0 * delta1 - pt1 * delta0) / (delta1 - delta0);
    offset = (1.0 - intersectionHeight) * perStep * float(numSteps);
    currentHeight = sampleHeightAtLevel(uv + offset, lod);
    ++samples;
    float delta = intersectionHeight - currentHeight;
    if (abs(delta) <= 0.01)
      break;
    if (delta < 0.0) {
      delta1 = delta;
      pt1 = intersectionHeight;
    } else {
      delta0 = delta;
      pt0 = intersectionHeight;
    }
  }
  // The relief fades out above the LOD threshold.
  offset *= 1.0 - clamp(lod - uEngineLodThreshold, 0.0, 1.0);
  return engineResult(uv + offset, dx, dy, samples);
}
#endif

ParallaxResult engineVisiblePoint(vec2 uv, vec3 V, vec2 dx, vec2 dy) {
#if defined(ENGINE_GODOT_OFFSET) || defined(ENGINE_GODOT_DEEP)
  return godotParallax(uv, V, dx, dy);
#elif defined(ENGINE_UNREAL_POM)
  return unrealParallax(uv, V, dx, dy);
#elif defined(ENGINE_URP_OFFSET)
  return urpParallax(uv, V, dx, dy);
#elif defined(ENGINE_HDRP_POM)
  return hdrpParallax(uv, V, dx, dy);
#else
  return engineResult(uv, dx, dy, 0);
#endif
}
