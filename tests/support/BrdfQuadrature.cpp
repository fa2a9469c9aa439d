// Quadrature of the glTF BRDF; see BrdfQuadrature.h.
#include "support/BrdfQuadrature.h"

#include "core/shading/Brdf.h"

#include <cmath>

namespace relief::test {

glm::vec3 directionalAlbedo(const glm::vec3& baseColor, float metallic, float roughness,
                            float nDotV, int thetaSteps) {
  const float pi = core::kPi;
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const glm::vec3 v(std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV);
  const int phiSteps = 2 * thetaSteps;
  const double dTheta = 0.5 * pi / thetaSteps;
  const double dPhi = 2.0 * pi / phiSteps;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < thetaSteps; ++i) {
    const double theta = (i + 0.5) * dTheta;
    const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    glm::dvec3 ring(0.0);
    for (int j = 0; j < phiSteps; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const glm::vec3 l(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)),
                        float(cosTheta));
      ring += glm::dvec3(core::gltfBrdf(baseColor, metallic, roughness, n, l, v));
    }
    sum += ring * cosTheta * sinTheta;
  }
  return glm::vec3(sum * dTheta * dPhi);
}

}  // namespace relief::test
