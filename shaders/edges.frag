#version 450 core
#include "common/clip_planes.glsl"
in vec3 vModelPosition;
in float vFade;
uniform vec3 color;
out vec4 fragColor;
void main() {
  if (clippedAway(vModelPosition) || vFade <= 0.0) discard;
  fragColor = vec4(color, vFade);
}
