// Whether the ray enters the mesh (or the visible part) through boundary face `code` (tet *
// 4 + face) at a parameter t in [tMin, tBefore): shared by the ray caster's entry search
// and the entry maps (entry_faces.frag), so that both decide every face alike. Needs
// common/tet_segment.glsl (the mesh) before it.
#include "common/edge_products.glsl"

bool entersThrough(uint code, float tMin, float tBefore, out float t) {
  uint tet = code >> 2;
  int k = int(code & 3u);
  uvec4 tv = tets[tet];
  mat4 P = cornersOf(tv);
  vec3 n, a;
  facePlane(P, k, n, a);
  float den = dot(n, rayDir);
  t = 0.0;
  if (den >= 0.0) return false;  // leaving through it, not entering
  t = dot(n, a - rayOrigin) / den;
  if (t < tMin || t >= tBefore) return false;
  // Through the triangle: the signs of the ray's products with its edges, the very numbers
  // the walk uses, so a ray through an edge shared by two boundary faces enters by exactly
  // one of them (and the walk agrees with it).
  ivec3 f = FACE[k];
  uint A = tv[f.x], B = tv[f.y], C = tv[f.z];
  vec3 p0 = P[f.x].xyz, p1 = P[f.y].xyz, p2 = P[f.z].xyz;
  float sAB = edgeProduct(A, B, p0, p1), sBC = edgeProduct(B, C, p1, p2), sCA = edgeProduct(C, A, p2, p0);
  bool outwardListing = dot(cross(p1 - p0, p2 - p0), n) > 0.0;  // then entering turns negative
  return outwardListing ? (sAB < 0.0 && sBC < 0.0 && sCA < 0.0) : (sAB > 0.0 && sBC > 0.0 && sCA > 0.0);
}
