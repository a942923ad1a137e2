#version 450 core
#include "common/clip_planes.glsl"
in vec3 vModelPosition;
uniform vec3 color;
out vec4 fragColor;
void main() {
  if (clippedAway(vModelPosition)) discard;
  fragColor = vec4(color, 1.0);
}
