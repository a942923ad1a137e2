#version 450 core
// Phong with the light at the camera, colored by the line's scalar.
#include "common/colormap.glsl"
#include "common/clip_planes.glsl"

in vec3 vViewPosition;
in vec3 vModelPosition;
in vec3 vViewNormal;
in float vValue;

uniform sampler1D colorMap;
uniform float valueMin;
uniform float valueMax;
uniform bool orthographic;
uniform vec3 lightDirection;
uniform vec3 noValueColor;

out vec4 fragColor;

void main() {
  if (clippedAway(vModelPosition)) discard;
  vec3 base = colorForValue(colorMap, vValue, valueMin, valueMax, noValueColor);
  vec3 N = normalize(vViewNormal);
  vec3 V = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
  if (dot(N, V) < 0.0) N = -N;
  vec3 L = normalize(lightDirection);
  float d = max(dot(N, L), 0.0);
  float s = pow(max(dot(reflect(-L, N), V), 0.0), 32.0);
  fragColor = vec4(base * (0.25 + 0.75 * d) + vec3(0.25 * s), 1.0);
}
