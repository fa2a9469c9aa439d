// Uniforms shared by every material shader: maps, material parameters, camera and light.
// Names mirror core's parameter names (core/Parameters.h) with a "u" prefix.

uniform sampler2D uColorMap;
uniform sampler2D uNormalMap;
uniform sampler2D uHeightMap;
uniform sampler2D uOcclusionMap;
uniform sampler2D uRoughnessMap;

uniform float uTiling;          // repeats across the mesh UV range
uniform float uNormalStrength;  // factor on the normal's tangent-plane tilt
uniform bool uNormalYDown;      // DirectX normal maps store +Y pointing down
uniform float uSpecular;        // highlight strength
uniform float uShininess;       // Blinn-Phong exponent

uniform vec3 uCameraPosition;   // world space
uniform vec3 uLightDirection;   // world space, unit, toward the light
uniform vec3 uLightColor;       // linear RGB times intensity
uniform float uAmbient;         // fraction of the albedo lit without direction
