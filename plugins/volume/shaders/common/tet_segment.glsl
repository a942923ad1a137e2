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

mat4 segmentCorners;  // the tet integrate() is in, for isoGradient
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

void integrate(mat4 P, uint tet, float t0, float t1) {
  if (tetShowsNothing(P, tet) || !clipSegment(t0, t1)) return;
  float sf = valueAt(P, tet, rayOrigin + t0 * rayDir), sb = valueAt(P, tet, rayOrigin + t1 * rayDir);
  segmentCorners = P;
  integrateValues(t0, t1, sf, sb);
}
