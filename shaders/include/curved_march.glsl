// The marches on a curved mesh (the curvedSilhouettes option): curved relief mapping
// (Oliveira and Policarpo 2005, "An Efficient Representation for Surface Details"), with the
// surface's curvature taken per pixel from screen-space derivatives instead of per vertex.
//
// Near the entry point the mesh is its tangent plane bent by its second fundamental form: at a
// UV offset d from the entry it lies z = 1/2 (L du^2 + 2 M du dv + N dv^2) (UV height units)
// off the plane, below it on a convex mesh. The eye ray, straight, at distance t (UV units
// along the tangent plane's ray -t V) is at -t V.z on the plane, so -t V.z - 1/2 k t^2 above
// the curved surface, k = L Vx^2 + 2 M Vx Vy + N Vy^2. On a convex mesh the ray passes through
// the relief's slab and out again: if it meets no height on the way, it misses the surface,
// and the pixel is left empty: the relief shapes the outline. On a flat mesh k = 0 and this is
// the march of parallax.glsl, stepped in t instead of in height.

// UvToWorld comes from displaced_position.glsl, which material.frag includes before this
// file (an include here would sit inside parallax.glsl's #ifdef and, included once, leave
// material.frag without it when the option is off).

// L, M, N per tiled UV unit in UV height units, set by material.frag before the march (the
// derivatives it needs must be taken in uniform control flow).
vec3 gSecondForm = vec3(0.0);
// Set by the march when the eye ray leaves the surface without meeting the relief.
bool gMissedSurface = false;

// The second fundamental form of the mesh surface at this pixel: the normal's derivatives and
// the position's (uvFrame), per texture u and v. Uniform control flow only.
vec3 secondFundamentalForm(vec3 normal, vec2 uv, UvToWorld uvFrame) {
  vec3 dndx = dFdx(normal);
  vec3 dndy = dFdy(normal);
  vec2 duvdx = dFdx(uv);
  vec2 duvdy = dFdy(uv);
  float determinant = duvdx.x * duvdy.y - duvdx.y * duvdy.x;
  if (abs(determinant) < 1e-14 || uvFrame.worldPerUv <= 0.0) return vec3(0.0);
  vec3 dndu = (dndx * duvdy.y - dndy * duvdx.y) / determinant;
  vec3 dndv = (dndy * duvdx.x - dndx * duvdy.x) / determinant;
  float l = -dot(uvFrame.dpdu, dndu);
  float m = -0.5 * (dot(uvFrame.dpdu, dndv) + dot(uvFrame.dpdv, dndu));
  float n = -dot(uvFrame.dpdv, dndv);
  // World units off the plane to the heights' UV units.
  return vec3(l, m, n) / uvFrame.worldPerUv;
}

// The ray's height above the curved surface at distance t.
float curvedRayHeight(float t, float vz, float k) {
  return -t * vz - 0.5 * k * t * t;
}

// The first t > tFrom where the ray's height above the curved surface is `level`, or -1:
// the roots of 1/2 k t^2 + vz t + level = 0, in the form that keeps the near root exact as k
// goes to 0 (on a flat mesh it is -level / vz; the textbook form cancels there).
float curvedRayReaches(float level, float tFrom, float vz, float k) {
  float discriminant = vz * vz - 2.0 * k * level;
  if (discriminant < 0.0) return -1.0;
  float q = -0.5 * (vz + sqrt(discriminant));
  float nearRoot = level / q;
  float farRoot = abs(k) > 1e-12 ? q / (0.5 * k) : -1.0;
  float first = min(nearRoot, farRoot);
  float second = max(nearRoot, farRoot);
  if (first > tFrom) return first;
  if (second > tFrom) return second;
  return -1.0;
}

ParallaxResult marchCurvedHeightField(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale,
                                      float bias, float mipLevel) {
  float vz = max(V.z, 1e-4);
  float k = gSecondForm.x * V.x * V.x + 2.0 * gSecondForm.y * V.x * V.y +
            gSecondForm.z * V.y * V.y;
  float top = scale + bias;
  float bottom = bias;
  // The ray enters the slab's top (above the mesh when the bias lifts the relief).
  float tStart = -top / vz;
  // It leaves through the bottom, where every height meets it, or, bent away on a convex
  // mesh, back out through the top.
  float tBottom = curvedRayReaches(bottom, tStart, vz, k);
  float tExit = tBottom > 0.0 ? tBottom : curvedRayReaches(top, tStart + 1e-6, vz, k);
  bool throughBottom = tBottom > 0.0;
  if (tExit <= tStart) {
    tExit = tStart + scale / vz;
    throughBottom = true;
  }
  int layers = marchLayers(V, scale, mipLevel);
  float dt = (tExit - tStart) / float(layers);

  float previousT = tStart;
  float previousGap = 1.0;  // ray height above the relief, in UV height units (> 0: above)
  float previousSample = 1.0;
  float t = tStart;
  float currentSample = 1.0;
  float gap = 1.0;
  int samples = 0;
  bool hit = false;
  for (int i = 0; i <= layers; ++i) {
    t = tStart + dt * float(i);
    currentSample = sampleHeight(uv - t * V.xy, dx, dy);
    ++samples;
    gap = curvedRayHeight(t, vz, k) - (currentSample * scale + bias);
    if (gap <= 0.0) {
      hit = true;
      break;
    }
    previousT = t;
    previousGap = gap;
    previousSample = currentSample;
  }
  ParallaxResult result;
  result.samples = samples;
  if (!hit && !throughBottom) {
    // The ray passed the relief: outside the outline. material.frag discards the pixel.
    gMissedSurface = true;
    result.uv = uv;
    result.height = 0.0;
    return result;
  }
#if defined(TECHNIQUE_STEEP)
  result.uv = uv - t * V.xy;
  result.height = currentSample;
#else
  float tAbove = previousT;
  float tBelow = t;
  float gapAbove = previousGap;
  float gapBelow = gap;
  if (samples == 1) {
    tAbove = tBelow;
    gapAbove = gapBelow;
  }
#if defined(TECHNIQUE_RELIEF)
  // Relief mapping's binary search on the bracket, as parallax.glsl does.
  for (int i = 0; i < uRefinementSteps && samples > 1; ++i) {
    float middle = 0.5 * (tAbove + tBelow);
    float h = sampleHeight(uv - middle * V.xy, dx, dy);
    ++result.samples;
    float middleGap = curvedRayHeight(middle, vz, k) - (h * scale + bias);
    if (middleGap <= 0.0) {
      tBelow = middle;
      gapBelow = middleGap;
    } else {
      tAbove = middle;
      gapAbove = middleGap;
    }
  }
#endif
  // The line through the bracket's two gaps (reference 001's intersection, in t).
  float ratio = gapAbove / max(gapAbove - gapBelow, 1e-9);
  float tHit = samples > 1 ? mix(tAbove, tBelow, clamp(ratio, 0.0, 1.0)) : tBelow;
  result.uv = uv - tHit * V.xy;
  result.height = sampleHeight(result.uv, dx, dy);
  ++result.samples;
#endif
  return result;
}
