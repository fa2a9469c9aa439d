// The directional albedo of the glTF BRDF by plain quadrature over the hemisphere of light
// directions (midpoint rule in theta and phi, no importance sampling): the independent
// reference the split-sum table and the PBR shader are checked against.
#pragma once

#include <glm/vec3.hpp>

namespace relief::test {

// Integral over l of f(l, v) (N.L) dl for a surface with normal +z seen at N.V = `nDotV`:
// the radiance it reflects from a uniform environment of radiance 1. `thetaSteps` x
// 2 thetaSteps points; 1024 resolves roughness down to about 0.2.
glm::vec3 directionalAlbedo(const glm::vec3& baseColor, float metallic, float roughness,
                            float nDotV, int thetaSteps = 1024);

}  // namespace relief::test
