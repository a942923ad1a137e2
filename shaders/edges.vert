#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 otherEnd;  // the segment's other endpoint
layout(location = 2) in float spacing;  // how far apart the edges around it are, over its length
layout(location = 3) in uint node;      // the surface vertex at this end (its value per node)
layout(location = 4) in uint cell;      // a surface face holding the edge (its value per cell)
// The surface's scalars (SurfaceRenderer): a wireframe is colored by the same values.
layout(std430, binding = 0) readonly buffer Scalars { float scalars[]; };
uniform mat4 modelView;
uniform mat4 projection;
uniform vec2 viewportSize;
// An edge shorter than this on screen (pixels) fades, gone at a third of it; 0: never.
uniform float densePixels = 0.0;
uniform int scalarLocation = -1;  // -1 the plain edge color, 0 per node, 1 per cell
out vec3 vModelPosition;  // relative to the model center, for the clip planes
out float vFade;          // 1 drawn in full, 0 not drawn: edges crowded into a few pixels
out float vValue;
out float vMissing;       // > 0 where an end has no value
const float NO_EDGE_VALUE = 1.0e38;
void main() {
  vModelPosition = position;
  gl_Position = projection * modelView * vec4(position, 1.0);
  float value = NO_EDGE_VALUE * 2.0;
  if (scalarLocation == 0 && node != 0xffffffffu) value = scalars[node];
  if (scalarLocation == 1 && cell != 0xffffffffu) value = scalars[cell];
  vMissing = value < NO_EDGE_VALUE ? 0.0 : 1.0;
  vValue = value < NO_EDGE_VALUE ? value : 0.0;
  vFade = 1.0;
  if (densePixels > 0.0) {
    // Both ends compute the same length, so the whole segment fades alike.
    vec4 other = projection * modelView * vec4(otherEnd, 1.0);
    if (gl_Position.w > 0.0 && other.w > 0.0) {
      float pixels = spacing * length((gl_Position.xy / gl_Position.w - other.xy / other.w) * 0.5 * viewportSize);
      float faint = densePixels / 3.0;
      vFade = clamp((pixels - faint) / (densePixels - faint), 0.0, 1.0);
    }
  }
}
