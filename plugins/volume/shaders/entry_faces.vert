#version 450 core
// The entry maps (TetRayDispatch::drawEntryMaps): every boundary face a ray may enter the
// mesh (or the visible part) by, drawn as its projected outline grown by a quarter pixel,
// so that every pixel whose ray may cross it gets a fragment; entry_faces.frag decides
// exactly, with the ray caster's own test. Faces that clearly turn away from the eye are
// left out (their rays leave through them).
layout(std430, binding = BINDING_NODES) readonly buffer Nodes { vec4 nodes[]; };
layout(std430, binding = BINDING_TETS) readonly buffer Tets { uvec4 tets[]; };
layout(std430, binding = BINDING_BOUNDARY_FACES) readonly buffer BoundaryFaces { uint boundaryFaces[]; };
#include "common/screen_outline.glsl"
uniform mat4 viewProjection;  // mesh-relative -> clip, y flipped: row 0 of the image is the top
uniform vec2 viewportSize;    // pixels
uniform mat4 inverseViewProjection;
uniform vec3 eye;             // mesh-relative (perspective)
uniform bool orthographic;

flat out uint vFace;

const ivec3 FACE_CORNERS[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 2, 3), ivec3(0, 1, 3), ivec3(0, 1, 2));

// True when every ray meets the face's plane from its inner side, by a margin no rounding
// reaches: then no ray enters through it.
bool turnsAway(vec3 p[3], vec3 opposite) {
  vec3 n = cross(p[1] - p[0], p[2] - p[0]);
  if (dot(n, opposite - p[0]) > 0.0) n = -n;  // outward
  vec3 toFace;
  if (orthographic) {
    vec4 a = inverseViewProjection * vec4(0.0, 0.0, -1.0, 1.0), b = inverseViewProjection * vec4(0.0, 0.0, 1.0, 1.0);
    toFace = b.xyz / b.w - a.xyz / a.w;
  } else {
    toFace = p[0] - eye;
  }
  return dot(n, toFace) > 1e-3 * length(n) * length(toFace);
}

void main() {
  uint code = boundaryFaces[gl_VertexID / 6];
  vFace = code;
  uvec4 tv = tets[code >> 2];
  int k = int(code & 3u);
  vec3 p[3];
  vec2 q[4];
  bool behindEye = false;
  for (int i = 0; i < 3; ++i) {
    p[i] = nodes[tv[FACE_CORNERS[k][i]]].xyz;
    vec4 c = viewProjection * vec4(p[i], 1.0);
    behindEye = behindEye || c.w <= 1e-6 * abs(c.z);
    q[i] = (c.xy / c.w * 0.5 + 0.5) * viewportSize;  // window pixels
  }
  if (turnsAway(p, nodes[tv[k]].xyz)) {  // no fragment
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  q[3] = q[2];  // a triangle: its hull is itself
  int corner = gl_VertexID % 6;
  vec2 hull[4];
  int count = behindEye ? 0 : projectedHull(q, hull);
  vec2 at;
  if (count > 0) {
    const int FAN[6] = int[6](0, 1, 2, 0, 2, 3);
    at = grown(hull, count, min(FAN[corner], count - 1));
  } else {  // behind the eye, or flat on screen: its box, or the whole screen
    vec2 lo = min(min(q[0], q[1]), q[2]) - MARGIN, hi = max(max(q[0], q[1]), q[2]) + MARGIN;
    if (behindEye) lo = vec2(0.0), hi = viewportSize;
    const vec2 BOX[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    at = mix(lo, hi, BOX[corner]);
  }
  gl_Position = vec4(at / viewportSize * 2.0 - 1.0, 0.0, 1.0);
}
