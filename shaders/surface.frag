#version 450 core
#include "common/colormap.glsl"
#include "common/clip_planes.glsl"

in vec3 vModelPosition;
in vec3 vViewPosition;
in vec3 vViewNormal;
in float vValue;
in float vMissing;

uniform sampler1D colorMap;
uniform float valueMin;
uniform float valueMax;
uniform int scalarLocation;
uniform bool lighting;
uniform bool orthographic;
uniform vec3 noValueColor;
uniform vec3 plainColor;
uniform float opacity;
uniform int colorBands;
uniform bool useBelowColor;
uniform vec3 belowColor;
uniform bool useAboveColor;
uniform vec3 aboveColor;
uniform bool logScale;  // colors by log10 of the value over log10 of the range (min > 0)

out vec4 fragColor;

void main() {
  if (clippedAway(vModelPosition)) discard;
  // On a log scale a value of 0 or below lies below any positive range.
  float value = logScale ? (vValue > 0.0 ? log(vValue) : -3.0e38) : vValue;
  float lo = logScale ? log(valueMin) : valueMin, hi = logScale ? log(valueMax) : valueMax;
  vec3 base = scalarLocation < 0 ? plainColor
             : vMissing > 0.0    ? noValueColor
                                 : colorForValueInRange(colorMap, value, lo, hi, noValueColor, colorBands,
                                                                        useBelowColor, belowColor, useAboveColor, aboveColor);
  if (lighting) {
    // Headlight, two-sided: a face seen head-on shows the exact color-map color.
    vec3 toEye = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
    float diffuse = abs(dot(normalize(vViewNormal), toEye));
    base *= 0.35 + 0.65 * diffuse;
  }
  fragColor = vec4(base, opacity);
}
