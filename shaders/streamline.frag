#version 450 core
// Illuminated lines (Zockler, Stalling & Hege 1996; Araujo & Farias): a line has no single
// normal, so lighting takes the normal in the plane of T and the light that maximises it:
// diffuse from sqrt(1 - (L.T)^2), raised to p = 4.8 (Banks 1994) so dense bundles keep
// their contrast; specular from the best reflection, sqrt(1-(L.T)^2) sqrt(1-(V.T)^2) -
// (L.T)(V.T). The light is attached to the camera.
#include "common/colormap.glsl"
#include "common/clip_planes.glsl"

in vec3 vViewPosition;
in vec3 vModelPosition;
in vec3 vViewTangent;
in float vValue;

uniform sampler1D colorMap;
uniform float valueMin;
uniform float valueMax;
uniform bool orthographic;
uniform vec3 lightDirection;  // view space, toward the light
uniform float ambient;
uniform float diffuse;
uniform float specular;
uniform float diffuseExponent;
uniform float shininess;
uniform vec3 noValueColor;

out vec4 fragColor;

void main() {
  if (clippedAway(vModelPosition)) discard;
  vec3 base = colorForValue(colorMap, vValue, valueMin, valueMax, noValueColor);
  vec3 T = normalize(vViewTangent);
  vec3 V = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
  vec3 L = normalize(lightDirection);
  float LT = dot(L, T), VT = dot(V, T);
  float sinL = sqrt(max(1.0 - LT * LT, 0.0)), sinV = sqrt(max(1.0 - VT * VT, 0.0));
  float d = pow(sinL, diffuseExponent);
  float s = pow(max(sinL * sinV - LT * VT, 0.0), shininess);
  fragColor = vec4(base * (ambient + diffuse * d) + vec3(specular * s), 1.0);
}
