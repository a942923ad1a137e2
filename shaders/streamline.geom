#version 450 core
// Each segment becomes a screen-aligned quad `lineWidth` pixels wide (core profile lines
// are one pixel), keeping its depth: lines hide and are hidden by surfaces.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 gViewPosition[];
in vec3 gModelPosition[];
in vec3 gViewTangent[];
in float gValue[];

uniform mat4 projection;
uniform vec2 viewportSize;  // pixels
uniform float lineWidth;    // pixels

out vec3 vViewPosition;
out vec3 vModelPosition;
out vec3 vViewTangent;
out float vValue;

void main() {
  vec4 c0 = projection * vec4(gViewPosition[0], 1.0), c1 = projection * vec4(gViewPosition[1], 1.0);
  if (c0.w <= 0.0 || c1.w <= 0.0) return;  // behind the eye
  vec2 s0 = c0.xy / c0.w * 0.5 * viewportSize, s1 = c1.xy / c1.w * 0.5 * viewportSize;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 side = len > 1e-6 ? vec2(-d.y, d.x) / len : vec2(1.0, 0.0);
  vec2 offset = side * 0.5 * lineWidth / (0.5 * viewportSize);  // NDC
  for (int i = 0; i < 2; ++i) {
    vec4 c = i == 0 ? c0 : c1;
    for (int k = -1; k <= 1; k += 2) {
      vViewPosition = gViewPosition[i];
      vModelPosition = gModelPosition[i];
      vViewTangent = gViewTangent[i];
      vValue = gValue[i];
      gl_Position = vec4(c.xy + float(k) * offset * c.w, c.zw);
      EmitVertex();
    }
  }
  EndPrimitive();
}
