// The tet parts of the ray caster (raycast.comp) and cell projection (vicp.frag): the mesh
// buffers, face planes, barycentric values and gradients, and the integration of one ray
// segment through one tet; the rest is common/volume_segment.glsl.
layout(std430, binding = BINDING_NODES) readonly buffer Nodes { vec4 nodes[]; };  // xyz mesh-relative, w nodal value
layout(std430, binding = BINDING_TETS) readonly buffer Tets { uvec4 tets[]; };
layout(std430, binding = BINDING_CELL_VALUES) readonly buffer CellValues { float cellValues[]; };

#include "common/volume_segment.glsl"

uniform bool cellField;

const ivec3 FACE[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 2, 3), ivec3(0, 1, 3), ivec3(0, 1, 2));

// A tet's corners as one load each: column k holds vertex k's position (xyz,
// mesh-relative) and its nodal value (w). Planes, values and gradients are computed from
// them, so a step through a tet reads each of its nodes once (on llvmpipe every buffer read
// is a gather with bounds checks: reading a node per plane cost more than the arithmetic).
mat4 cornersOf(uvec4 tv) { return mat4(nodes[tv.x], nodes[tv.y], nodes[tv.z], nodes[tv.w]); }

// Outward normal and a point of face k.
void facePlane(mat4 P, int k, out vec3 n, out vec3 a) {
  vec3 p0 = P[FACE[k].x].xyz, p1 = P[FACE[k].y].xyz, p2 = P[FACE[k].z].xyz;
  n = cross(p1 - p0, p2 - p0);
  if (dot(n, P[k].xyz - p0) > 0.0) n = -n;
  a = p0;
}

float valueAt(mat4 P, uint tet, vec3 p) {
  if (cellField) return cellValues[tet];
  // Barycentric weights from the face planes: lambda_k = distance to face k / height.
  float s = 0.0;
  for (int k = 0; k < 4; ++k) {
    vec3 n, a;
    facePlane(P, k, n, a);
    s += P[k].w * dot(n, a - p) / dot(n, a - P[k].xyz);
  }
  return s;
}

vec3 gradientOf(mat4 P) {  // of the linear scalar: sum_k s_k grad(lambda_k)
  vec3 g = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    vec3 n, a;
    facePlane(P, k, n, a);
    g -= P[k].w * n / dot(n, a - P[k].xyz);
  }
  return g;
}

mat4 segmentCorners;  // the tet integrateSegment() is in, for isoGradient
vec3 isoGradient(float t) { return cellField ? vec3(0.0) : gradientOf(segmentCorners); }

// True when nothing in the tet can show: its values all lie where the extinction is zero
// and no iso-surface passes through them. Decided from its values before any plane or
// barycentric weight is computed.
bool tetShowsNothing(mat4 P, uint tet) {
  float lo, hi;
  if (cellField) {
    lo = hi = cellValues[tet];
  } else {
    lo = min(min(P[0].w, P[1].w), min(P[2].w, P[3].w));
    hi = max(max(P[0].w, P[1].w), max(P[2].w, P[3].w));
  }
  for (int i = 0; i < isoCount; ++i)
    if (isoValue[i] >= lo && isoValue[i] <= hi) return false;
  return tfTransparent(lo, hi);
}

// The value where the ray crosses face k (opposite vertex k) at parameter t, from the face's
// three vertices taken in ascending index order, so that the two tets of a face compute
// the same number at the same parameter. From each tet's own planes the two values differ
// by a rounding, and an iso-surface through that point would lie in (sf, sb] of both and be
// drawn twice (seen on the wheel: a pixel 0.038 too opaque; 0.24 on a surface lying on
// inner faces). False for a face flat in float.
bool faceValue(mat4 P, uvec4 tv, int k, float t, out float value) {
  ivec3 f = FACE[k];
  vec4 A = P[f.x], B = P[f.y], C = P[f.z], swap;
  uint a = tv[f.x], b = tv[f.y], c = tv[f.z], id;
  // Sorted by swapping the values (selects), not by indexing the corners with the sorted order.
  if (a > b) { swap = A; A = B; B = swap; id = a; a = b; b = id; }
  if (b > c) { swap = B; B = C; C = swap; id = b; b = c; c = id; }
  if (a > b) { swap = A; A = B; B = swap; }
  precise vec3 p = rayOrigin + t * rayDir;
  precise vec3 n = cross(B.xyz - A.xyz, C.xyz - A.xyz);
  precise float wA = dot(n, cross(B.xyz - p, C.xyz - p));
  precise float wB = dot(n, cross(C.xyz - p, A.xyz - p));
  precise float wC = dot(n, cross(A.xyz - p, B.xyz - p));
  precise float sum = wA + wB + wC;
  value = 0.0;
  if (!(abs(sum) > 0.0)) return false;
  value = (wA * A.w + wB * B.w + wC * C.w) / sum;
  return true;
}

// The value at parameter t: on face k (k >= 0: the segment starts or ends there, unclipped)
// from that face alone where iso-surfaces are drawn (elsewhere a rounding between
// neighbours changes nothing visible, and the planes cost less here), else from the tet's
// planes.
float segmentEndValue(mat4 P, uvec4 tv, uint tet, int k, float t) {
  float v;
  if (isoCount > 0 && !cellField && k >= 0 && faceValue(P, tv, k, t, v)) return v;
  return valueAt(P, tet, rayOrigin + t * rayDir);
}

// Integrates the ray over [t0, t1] in the tet. frontFace and backFace: the faces the segment
// starts and ends on (-1 where an end lies elsewhere: the near plane, opaque geometry);
// values there come from the face, so neighbours agree on them (faceValue).
void integrateSegment(mat4 P, uvec4 tv, uint tet, float t0, float t1, int frontFace, int backFace) {
  float c0 = t0, c1 = t1;
  if (tetShowsNothing(P, tet) || !clipSegment(c0, c1)) return;
  float sf = segmentEndValue(P, tv, tet, c0 == t0 ? frontFace : -1, c0);
  float sb = segmentEndValue(P, tv, tet, c1 == t1 ? backFace : -1, c1);
  segmentCorners = P;
  integrateValues(c0, c1, sf, sb);
}
