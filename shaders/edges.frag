#version 450 core
#include "common/colormap.glsl"
#include "common/clip_planes.glsl"
in vec3 vModelPosition;
in float vFade;
in float vValue;
in float vMissing;
uniform vec3 color;
uniform int scalarLocation = -1;  // >= 0: colored by the values as the surface is (a wireframe)
uniform sampler1D colorMap;
uniform float valueMin;
uniform float valueMax;
uniform vec3 noValueColor;
uniform int colorBands;
uniform bool logScale;
uniform bool useBelowColor;
uniform vec3 belowColor;
uniform bool useAboveColor;
uniform vec3 aboveColor;
out vec4 fragColor;
void main() {
  if (clippedAway(vModelPosition) || vFade <= 0.0) discard;
  vec3 c = color;
  if (scalarLocation >= 0) {
    float value = logScale ? (vValue > 0.0 ? log(vValue) : -3.0e38) : vValue;
    float lo = logScale ? log(valueMin) : valueMin, hi = logScale ? log(valueMax) : valueMax;
    c = vMissing > 0.0 ? noValueColor
                       : colorForValueInRange(colorMap, value, lo, hi, noValueColor, colorBands, useBelowColor,
                                              belowColor, useAboveColor, aboveColor);
  }
  fragColor = vec4(c, vFade);
}
