#version 450 core
// Boundary surface: positions relative to the model center, one scalar per node or cell
// fetched from an SSBO so that changing the result re-uploads only the scalars.
#include "common/colormap.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in uint node;
layout(location = 3) in uint cell;

layout(std430, binding = 0) readonly buffer Scalars { float scalars[]; };

uniform mat4 modelView;
uniform mat4 projection;
uniform int scalarLocation;  // -1 none, 0 per node, 1 per cell

out vec3 vModelPosition;  // relative to the model center, for the clip planes
out vec3 vViewPosition;
out vec3 vViewNormal;
out float vValue;
out float vMissing;  // > 0 where any vertex of the triangle has no value

void main() {
  vec4 viewPos = modelView * vec4(position, 1.0);
  vModelPosition = position;
  vViewPosition = viewPos.xyz;
  vViewNormal = mat3(modelView) * normal;  // rotation + translation only: no inverse needed
  float value = scalarLocation == 0 ? scalars[node] : scalarLocation == 1 ? scalars[cell] : 0.0;
  // Interpolating the sentinel itself would smear huge values over the triangle.
  vMissing = value < NO_VALUE ? 0.0 : 1.0;
  vValue = value < NO_VALUE ? value : 0.0;
  gl_Position = projection * viewPos;
}
