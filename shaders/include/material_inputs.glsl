// Uniforms shared by every material shader: maps, material parameters, camera and light.
// Names mirror core's parameter names (core/Parameters.h) with a "u" prefix. Switches that
// change the code (technique, shadow mode, UV edge, depth offset, packed height, debug view)
// are #defines prepended by the renderer instead (renderer/ShaderVariant.cpp).

// Each map slot's sampler (uColorMap, uNormalMap, uHeightMap, uOcclusionMap, uRoughnessMap,
// uMetallicMap) and, for a slot sampled only when the material has its map, its presence flag
// (uHasOcclusionMap, uHasRoughnessMap, uHasMetallicMap: an empty slot is not sampled and its
// neutral value is used instead, a texture fetch saved per pixel for each, which llvmpipe
// feels). The renderer #defines this from core/material/MapSlot.cpp's rows
// (renderer/ShaderVariant.cpp, materialTableDefines), so a new slot needs no line here.
MAP_SLOT_UNIFORMS
uniform vec2 uHeightMapSize;    // texels, for views measured in texels
uniform float uHeightQuantum;   // the height map's step: 1/255 for 8 bits, 0 for float

uniform float uHeightScale;     // UV units spanned by heights 0..1
uniform float uHeightBias;      // UV units; -uHeightScale puts the top on the surface
uniform bool uHeightIsDepth;    // the height map stores depth (white = deepest)
uniform int uMinSamples;        // view-ray samples looking straight on (reference 001)
uniform int uMaxSamples;        // view-ray samples at grazing angles
uniform float uSamplesPerTexel; // view-ray samples per height texel crossed; 0: by angle only
uniform int uRefinementSteps;   // relief mapping's binary search steps
uniform float uLodFade;         // mip level where the relief has faded out; 0 = never
uniform int uMaxTessellation;   // displacement: most segments per triangle edge

uniform float uShadowStrength;  // 0..1
uniform int uShadowSamples;     // samples toward the light
uniform float uShadowSoftness;  // angular diameter of the light, radians
uniform bool uShadowLimit;      // Welsh's limit on the light ray (reference 003, 1.3)

uniform float uTiling;          // repeats across the mesh UV range (times the view's preview's)
uniform float uWorldPerUv;      // world units per unit of mesh UV (core::worldUnitsPerUv)
uniform bool uTileSeams;        // the view's tile preview: lines where the map's edges meet
uniform float uNormalStrength;  // factor on the normal's tangent-plane tilt
uniform bool uNormalYDown;      // DirectX normal maps store +Y pointing down
uniform bool uNormalTwoChannel; // the normal texture holds X, Y only (BC5, EAC RG11, DXT5nm)
uniform float uSpecular;        // highlight strength
uniform float uShininess;       // Blinn-Phong exponent
uniform float uMetallic;        // glTF metallicFactor
uniform float uRoughness;       // glTF roughnessFactor (perceptual)
uniform sampler2D uSplitSumLut; // (A, B) over N.V (s) and roughness (t) (core/shading)

uniform vec3 uCameraPosition;   // world space
uniform mat4 uViewProjection;
uniform vec3 uLightDirection;   // world space, unit, toward the light
uniform vec3 uLightColor;       // linear RGB times intensity
uniform float uAmbient;         // classic: fraction of the albedo lit without direction
uniform float uExposure;        // display: 2^EV on the radiance
uniform int uToneMapper;        // display: 0 none, 1 Khronos PBR Neutral, 2 ACES (core/view/DisplayTransform)
uniform vec2 uDepthDisplayRange;  // world distances mapped to black..white in the depth view

// Map textures keep their rows top first, as image files and compressed blocks store them
// (renderer/CompressedUpload.h), while texture V runs upward from the mesh's UV origin at the
// image's bottom-left: every lookup flips V here, gradients with it.
vec2 mapCoordinates(vec2 uv) {
  return vec2(uv.x, 1.0 - uv.y);
}

vec4 sampleMap(sampler2D map, vec2 uv, vec2 dx, vec2 dy) {
  return textureGrad(map, mapCoordinates(uv), vec2(dx.x, -dx.y), vec2(dy.x, -dy.y));
}
