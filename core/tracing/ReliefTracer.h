// The exact reference for every parallax technique: the intersection of a ray with the
// bilinearly interpolated height field (HeightField), found analytically cell by cell. The
// ray walks the grid of texel centres (a 2D DDA); inside a cell the bilinear surface along a
// straight ray is a quadratic in the ray parameter, so the first crossing is a root of a
// quadratic, solved in double precision and polished by bisection. Accurate to far better than
// 1e-4 texel. Used by the tests and by the viewport's `error` view.
#pragma once

#include "core/tracing/HeightField.h"

#include <glm/glm.hpp>

namespace relief::core::inline tracing {

struct ViewRayHit {
  bool hit = false;
  glm::dvec2 uv{0.0};   // texture UV of the visible surface point
  double height = 0.0;  // its height in UV units above the mesh surface
  int cellsVisited = 0;
};

// `entryUv`: the texture UV where the eye ray meets the mesh surface (mesh UV times tiling).
// `viewTangent`: unit vector from the surface toward the eye in tangent space (z > 0).
// The ray starts above the highest texel and ends below the lowest, so a field always gets hit
// unless the ray is parallel to the surface.
ViewRayHit traceViewRay(const HeightField& field, glm::dvec2 entryUv, glm::dvec3 viewTangent);

struct ShadowRayHit {
  bool occluded = false;
  double distance = 0.0;  // along the ray (UV units) to the first occluder
};

// From the surface point (uv, height) toward the light (`lightTangent`, unit, z > 0): is the
// height field above the ray anywhere before the ray leaves the field's top?
ShadowRayHit traceShadowRay(const HeightField& field, glm::dvec2 uv, double height,
                            glm::dvec3 lightTangent);

}  // namespace relief::core::inline tracing
