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

const float MARGIN = 0.25;  // pixels: far beyond the rasterizer's snapping (1/256 px)

float orient(vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool crosses(vec2 a, vec2 b, vec2 c, vec2 d) {  // segments ab and cd properly cross
  return orient(a, b, c) * orient(a, b, d) < 0.0 && orient(c, d, a) * orient(c, d, b) < 0.0;
}

bool inside(vec2 p, vec2 a, vec2 b, vec2 c) {
  float o = orient(a, b, c);
  return orient(a, b, p) * o >= 0.0 && orient(b, c, p) * o >= 0.0 && orient(c, a, p) * o >= 0.0;
}

// The hull of the projected vertices in counter-clockwise order: 3 or 4 corners; 0 when it
// is degenerate (collinear or coincident points), then the bounding box is drawn instead.
int projectedHull(vec2 q[4], out vec2 hull[4]) {
  int count = 0;
  for (int i = 0; i < 4 && count == 0; ++i) {
    vec2 a = q[(i + 1) % 4], b = q[(i + 2) % 4], c = q[(i + 3) % 4];
    if (inside(q[i], a, b, c) && orient(a, b, c) != 0.0) {
      hull[0] = a; hull[1] = b; hull[2] = c; hull[3] = c;
      count = 3;
    }
  }
  if (count == 0) {  // a quadrilateral: its diagonals are the pair of segments that cross
    if (crosses(q[0], q[2], q[1], q[3])) { hull[0] = q[0]; hull[1] = q[1]; hull[2] = q[2]; hull[3] = q[3]; count = 4; }
    else if (crosses(q[0], q[1], q[2], q[3])) { hull[0] = q[0]; hull[1] = q[2]; hull[2] = q[1]; hull[3] = q[3]; count = 4; }
    else if (crosses(q[0], q[3], q[1], q[2])) { hull[0] = q[0]; hull[1] = q[1]; hull[2] = q[3]; hull[3] = q[2]; count = 4; }
  }
  if (count > 0 && orient(hull[0], hull[1], hull[2]) < 0.0) {
    vec2 t = hull[1]; hull[1] = hull[count - 1]; hull[count - 1] = t;  // (0 1 2 [3]) -> (0 [3] 2 1)
  }
  return count;
}

// Corner i of the hull moved out so that every edge moves out by MARGIN (mitred; at very
// sharp corners the mitre is capped, the corner still moves outward).
vec2 grown(vec2 hull[4], int count, int i) {
  vec2 prev = hull[(i + count - 1) % count], here = hull[i], next = hull[(i + 1) % count];
  vec2 e0 = normalize(here - prev), e1 = normalize(next - here);
  vec2 n0 = vec2(e0.y, -e0.x), n1 = vec2(e1.y, -e1.x);  // outward for counter-clockwise
  vec2 miter = n0 + n1;
  float len = length(miter);
  if (len < 1e-6) return here + MARGIN * n0;
  miter /= len;
  return here + miter * (MARGIN / max(dot(miter, n0), 0.125));
}

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
