#version 450 core
// View-independent cell projection (Weiler et al. 2003): every tet is drawn, in the order
// of the sorted index list, from the GPU-resident mesh (vertex pulling: no geometry
// travels per frame, only the order). Each tet is drawn as the outline of its projection
// (the convex hull of its four projected vertices, a triangle or a quadrilateral, grown by
// a quarter of a pixel) in two triangles, so each pixel gets at most one fragment per tet;
// vicp.frag decides exactly which of them the ray crosses and over which interval.
//
// Why not the tet's own faces: the rasterizer decides coverage on snapped screen
// positions, and where a ray runs through a chain of vertices or inside a face (grids
// seen along a diagonal) it may hand the pixel to a tet the ray only touches while the
// tet the ray really crosses gets nothing. Deciding it in the fragment, with one plane
// per shared face, loses nothing and counts nothing twice, as the CPU reference does.
layout(std430, binding = BINDING_NODES) readonly buffer Nodes { vec4 nodes[]; };
layout(std430, binding = BINDING_TETS) readonly buffer Tets { uvec4 tets[]; };
layout(std430, binding = BINDING_ORDER) readonly buffer Order { uint order[]; };
#include "common/hidden_tets.glsl"
uniform mat4 viewProjection;  // mesh-relative -> clip, y flipped: row 0 of the image is the top
uniform vec2 viewportSize;    // pixels

flat out uint vTet;

#include "common/screen_outline.glsl"

void main() {
  uint tet = order[gl_VertexID / 6];
  vTet = tet;
  if (tetHidden(int(tet))) {  // nothing to draw: outside the clip volume, no fragment
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  uvec4 tv = tets[tet];
  vec2 q[4];
  bool behindEye = false;
  for (int k = 0; k < 4; ++k) {
    vec4 c = viewProjection * vec4(nodes[tv[k]].xyz, 1.0);
    behindEye = behindEye || c.w <= 1e-6 * abs(c.z);
    q[k] = (c.xy / c.w * 0.5 + 0.5) * viewportSize;  // window pixels
  }
  int corner = gl_VertexID % 6;
  vec2 hull[4];
  int count = behindEye ? 0 : projectedHull(q, hull);
  vec2 p;
  if (count > 0) {
    // Two triangles: (0 1 2) and (0 2 3); a triangular hull repeats its last corner.
    const int FAN[6] = int[6](0, 1, 2, 0, 2, 3);
    p = grown(hull, count, min(FAN[corner], count - 1));
  } else {
    // No bounded or no proper outline (behind the eye, or flat on screen): its box, or the
    // whole screen.
    vec2 lo = min(min(q[0], q[1]), min(q[2], q[3])) - MARGIN, hi = max(max(q[0], q[1]), max(q[2], q[3])) + MARGIN;
    if (behindEye) lo = vec2(0.0), hi = viewportSize;
    const vec2 BOX[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    p = mix(lo, hi, BOX[corner]);
  }
  gl_Position = vec4(p / viewportSize * 2.0 - 1.0, 0.0, 1.0);
}
