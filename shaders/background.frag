// A quiet vertical gradient behind the material: neutral grey, so it does not tint judgement
// of colour, and dark, so highlights read clearly.

#include "include/color.glsl"

in vec2 vScreen;
out vec4 fragColor;

uniform vec3 uTopColor;     // linear RGB
uniform vec3 uBottomColor;  // linear RGB

void main() {
  fragColor = vec4(linearToSrgb(mix(uBottomColor, uTopColor, vScreen.y)), 1.0);
}
