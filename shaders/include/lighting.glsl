// Blinn-Phong in tangent space (reference 004): I = sat(N.L) * diffuse + sat(N.H)^n * specular,
// plus an ambient term scaled by the AO map. Self-shadowing scales the direct light.

struct SurfaceSample {
  vec3 normal;      // tangent space, unit
  vec3 albedo;      // linear RGB
  float occlusion;  // 1 = fully open
  float roughness;  // 0 = the material's shininess, 1 = matte
  float metallic;   // pbr only: 0 dielectric, 1 metal
};

vec3 shadeBlinnPhong(SurfaceSample surface, vec3 lightTangent, vec3 viewTangent, float shadow) {
  vec3 l = normalize(lightTangent);
  vec3 v = normalize(viewTangent);
  vec3 h = normalize(l + v);
  float nDotL = max(dot(surface.normal, l), 0.0);
  // A normal map can tilt a texel toward a light that is below the geometric surface; fade the
  // direct light out over the last few degrees above the horizon (l.z is the geometric N.L) so
  // faces turned away from the light go dark instead of glowing.
  float horizon = clamp(l.z * 8.0, 0.0, 1.0);
  float exponent = max(1.0, uShininess * (1.0 - surface.roughness) * (1.0 - surface.roughness));
  float specular = uSpecular * (1.0 - surface.roughness) *
                   pow(max(dot(surface.normal, h), 0.0), exponent) * step(0.0, nDotL);
  float lit = horizon * (1.0 - uShadowStrength * shadow);
  vec3 direct = (surface.albedo * nDotL + vec3(specular)) * uLightColor * lit;
  vec3 ambient = surface.albedo * uAmbient * surface.occlusion;
  return direct + ambient;
}
