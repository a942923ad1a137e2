// The tet parts of the ray caster (raycast.comp) and cell projection (vicp.frag): the mesh
// buffers, face planes, barycentric values and gradients, and the integration of one ray
// segment through one tet; the rest is common/volume_segment.glsl.
layout(std430, binding = BINDING_NODES) readonly buffer Nodes { vec4 nodes[]; };  // xyz mesh-relative, w nodal value
layout(std430, binding = BINDING_TETS) readonly buffer Tets { uvec4 tets[]; };
layout(std430, binding = BINDING_CELL_VALUES) readonly buffer CellValues { float cellValues[]; };

#include "common/volume_segment.glsl"

uniform bool cellField;

const ivec3 FACE[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 2, 3), ivec3(0, 1, 3), ivec3(0, 1, 2));

// Outward normal and a point of face k of tet t.
void facePlane(uvec4 tv, int k, out vec3 n, out vec3 a) {
  vec3 p0 = nodes[tv[FACE[k].x]].xyz, p1 = nodes[tv[FACE[k].y]].xyz, p2 = nodes[tv[FACE[k].z]].xyz;
  n = cross(p1 - p0, p2 - p0);
  if (dot(n, nodes[tv[k]].xyz - p0) > 0.0) n = -n;
  a = p0;
}

float valueAt(uvec4 tv, uint tet, vec3 p) {
  if (cellField) return cellValues[tet];
  // Barycentric weights from the face planes: lambda_k = distance to face k / height.
  float s = 0.0;
  for (int k = 0; k < 4; ++k) {
    vec3 n, a;
    facePlane(tv, k, n, a);
    s += nodes[tv[k]].w * dot(n, a - p) / dot(n, a - nodes[tv[k]].xyz);
  }
  return s;
}

vec3 gradientOf(uvec4 tv) {  // of the linear scalar: sum_k s_k grad(lambda_k)
  vec3 g = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    vec3 n, a;
    facePlane(tv, k, n, a);
    g -= nodes[tv[k]].w * n / dot(n, a - nodes[tv[k]].xyz);
  }
  return g;
}

uvec4 segmentTet;  // the tet integrate() is in, for isoGradient
vec3 isoGradient(float t) { return cellField ? vec3(0.0) : gradientOf(segmentTet); }

void integrate(uvec4 tv, uint tet, float t0, float t1) {
  if (!clipSegment(t0, t1)) return;
  float sf = valueAt(tv, tet, rayOrigin + t0 * rayDir), sb = valueAt(tv, tet, rayOrigin + t1 * rayDir);
  segmentTet = tv;
  integrateValues(t0, t1, sf, sb);
}
