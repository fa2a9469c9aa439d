// The marches on a curved mesh (the curvedSilhouettes option): curved relief mapping
// (Oliveira and Policarpo 2005, "An Efficient Representation for Surface Details"), with the
// surface's curvature taken per pixel from screen-space derivatives instead of per vertex.
//
// In the plane of the eye ray and the normal, the mesh is taken as its osculating circle at the
// entry point: radius 1/kappa, kappa the normal curvature along the ray's direction (from the
// second fundamental form, L du^2 + 2 M du dv + N dv^2 over the squared length), centred below
// a convex mesh. The relief's levels are the concentric circles at their heights, as the
// displacement technique's offset surfaces are on a sphere or a cylinder; the straight eye ray
// is measured against them exactly, and a point of the ray is read at the texture position the
// same angle around the centre reaches on the mesh (the arc, not the chord). Oliveira and
// Policarpo's quadratic (z = 1/2 kappa x^2) is this circle's first term; at the outline, where
// the ray runs far and the relief is a tenth of the radius deep, the quadratic kept the floor's
// outline too wide (a sphere's floor curves away faster than its top: radius R - depth). On a
// convex mesh the ray passes through the relief's slab and out again: if it meets no height
// on the way, it misses the surface, and the pixel is left empty: the relief shapes the
// outline. On a flat mesh kappa = 0 and this is the march of parallax.glsl, stepped in t
// instead of in height.
//
// Lengths here are in height units (UV units of the mesh's world-per-UV factor,
// toUvHeightSpace), t is the march's parameter along V (uv - t V.xy without curvature).

// UvToWorld comes from displaced_position.glsl, which material.frag includes before this
// file (an include here would sit inside parallax.glsl's #ifdef and, included once, leave
// material.frag without it when the option is off).

// The eye ray's curvature, set by material.frag before the march (the derivatives it needs
// must be taken in uniform control flow).
struct CurvedRay {
  float kappa;        // normal curvature along the ray, per height unit (> 0: convex)
  float lateralRate;  // distance along the surface's tangent plane per unit of t
};
CurvedRay gCurvedRay = CurvedRay(0.0, 0.0);
// Set by the march when the eye ray leaves the surface without meeting the relief.
bool gMissedSurface = false;

// The second fundamental form of the mesh surface at this pixel, in world units per squared
// tiled UV unit: the normal's derivatives and the position's (uvFrame), per texture u and v.
// Negative along directions in which a mesh with outward normals is convex. Uniform control
// flow only.
vec3 secondFundamentalForm(vec3 normal, vec2 uv, UvToWorld uvFrame) {
  vec3 dndx = dFdx(normal);
  vec3 dndy = dFdy(normal);
  vec2 duvdx = dFdx(uv);
  vec2 duvdy = dFdy(uv);
  float determinant = duvdx.x * duvdy.y - duvdx.y * duvdy.x;
  if (abs(determinant) < 1e-14) return vec3(0.0);
  vec3 dndu = (dndx * duvdy.y - dndy * duvdx.y) / determinant;
  vec3 dndv = (dndy * duvdx.x - dndx * duvdy.x) / determinant;
  float l = -dot(uvFrame.dpdu, dndu);
  float m = -0.5 * (dot(uvFrame.dpdu, dndv) + dot(uvFrame.dpdv, dndu));
  float n = -dot(uvFrame.dpdv, dndv);
  return vec3(l, m, n);
}

// The curvature of the eye ray's plane: `worldForm` from secondFundamentalForm, `eye` the
// unnormalised toUvHeightSpace direction to the eye (whose xy over heightToWorld is UV per world
// unit of the ray, z the cosine to the normal).
CurvedRay curvedRayOf(vec3 worldForm, vec3 eye, float heightToWorld) {
  CurvedRay ray = CurvedRay(0.0, 0.0);
  float along = length(eye);
  float sine2 = max(1.0 - eye.z * eye.z, 0.0);
  if (along <= 0.0 || heightToWorld <= 0.0 || sine2 < 1e-8) return ray;
  vec2 uvPerWorld = eye.xy / heightToWorld;
  float form = worldForm.x * uvPerWorld.x * uvPerWorld.x +
               2.0 * worldForm.y * uvPerWorld.x * uvPerWorld.y +
               worldForm.z * uvPerWorld.y * uvPerWorld.y;
  ray.kappa = -form / sine2 * heightToWorld;  // per world unit, then per height unit
  ray.lateralRate = sqrt(sine2) / along;
  return ray;
}

// The ray's height above the mesh at t: its distance from the circle's centre less the radius,
// (kappa (x^2 + z^2) + 2 z) / (1 + kappa r) in the form that holds as kappa goes to 0 (and,
// with the centre above, on a concave mesh).
float curvedRayHeight(float t, float vz) {
  float x = t * gCurvedRay.lateralRate;
  float z = -t * vz;
  float kappa = gCurvedRay.kappa;
  float kx = kappa * x;
  float kz = 1.0 + kappa * z;
  return (kappa * (x * x + z * z) + 2.0 * z) / (1.0 + sqrt(kx * kx + kz * kz));
}

// Where the ray at t is read: the texture position on the mesh at the same angle around the
// circle's centre (the arc over the chord's foot, x: 1 on a flat mesh).
vec2 curvedRayUv(vec2 uv, vec3 V, float t) {
  float x = t * gCurvedRay.lateralRate;
  float kappa = gCurvedRay.kappa;
  float bend = abs(kappa * x);
  float arcOverChord = 1.0;
  if (bend > 1e-4) arcOverChord = atan(bend, 1.0 - kappa * t * V.z) / bend;
  return uv - t * arcOverChord * V.xy;
}

// The first t > tFrom where the ray's height above the mesh is `level`, or -1: where its
// distance from the centre is the radius plus the level, kappa rho^2 t^2 - 2 vz t - (2 level +
// kappa level^2) = 0 (rho^2 t^2 the squared distance along the ray), in the form that keeps the
// near root exact as kappa goes to 0 (there it is -level / vz).
float curvedRayReaches(float level, float tFrom, float vz) {
  float kappa = gCurvedRay.kappa;
  float a = kappa * (gCurvedRay.lateralRate * gCurvedRay.lateralRate + vz * vz);
  float c = -(2.0 * level + kappa * level * level);
  float discriminant = vz * vz - a * c;
  if (discriminant < 0.0) return -1.0;
  float q = vz + sqrt(discriminant);
  float nearRoot = -c / q;
  float farRoot = abs(a) > 1e-12 ? q / a : -1.0;
  float first = min(nearRoot, farRoot);
  float second = max(nearRoot, farRoot);
  if (first > tFrom) return first;
  if (second > tFrom) return second;
  return -1.0;
}

ParallaxResult marchCurvedHeightField(vec2 uv, vec3 V, vec2 dx, vec2 dy, float scale,
                                      float bias, float mipLevel) {
  float vz = max(V.z, 1e-4);
  float top = scale + bias;
  float bottom = bias;
  // The ray enters the slab's top (above the mesh when the bias lifts the relief).
  float tStart = -top / vz;
  // It leaves through the bottom, where every height meets it, or, bent away on a convex
  // mesh, back out through the top.
  float tBottom = curvedRayReaches(bottom, tStart, vz);
  float tExit = tBottom > 0.0 ? tBottom : curvedRayReaches(top, tStart + 1e-6, vz);
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
    currentSample = sampleHeight(curvedRayUv(uv, V, t), dx, dy);
    ++samples;
    gap = curvedRayHeight(t, vz) - (currentSample * scale + bias);
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
  result.uv = curvedRayUv(uv, V, t);
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
    float h = sampleHeight(curvedRayUv(uv, V, middle), dx, dy);
    ++result.samples;
    float middleGap = curvedRayHeight(middle, vz) - (h * scale + bias);
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
  result.uv = curvedRayUv(uv, V, tHit);
  result.height = sampleHeight(result.uv, dx, dy);
  ++result.samples;
#endif
  return result;
}
