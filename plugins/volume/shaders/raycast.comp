#version 450 core
// GPU ray casting through tetrahedra, one invocation per pixel: enter at a boundary face
// (found in a BVH over boundary faces, which also finds where a ray re-enters a
// non-convex mesh), walk tet to tet through face adjacency, leave each tet through the
// face with the smallest exit parameter, integrate each segment (three modes), composite
// front to back, stop early when nearly opaque.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D outImage;
layout(std430, binding = BINDING_NEIGHBORS) readonly buffer Neighbors { ivec4 neighbors[]; };
layout(std430, binding = BINDING_BVH) readonly buffer Bvh { vec4 bvh[]; };
layout(std430, binding = BINDING_BOUNDARY_FACES) readonly buffer BoundaryFaces { uint boundaryFaces[]; };
uniform int maxSteps;

#include "common/tet_segment.glsl"

// Nearest entry (front-facing boundary face) hit with parameter >= tMin, other than the
// face `excluded` (tet * 4 + face); -1 if none.
int findEntry(float tMin, uint excluded, out float tHit, out int faceOut) {
  int best = -1;
  tHit = 3.4e38;
  uint stack[64];
  int top = 0;
  stack[top++] = 0u;
  vec3 inv = 1.0 / rayDir;
  while (top > 0) {
    uint node = stack[--top];
    vec4 lo = bvh[2u * node], hi = bvh[2u * node + 1u];
    vec3 t0 = (lo.xyz - rayOrigin) * inv, t1 = (hi.xyz - rayOrigin) * inv;
    vec3 tn = min(t0, t1), tx = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, tMin)), leave = min(min(tx.x, tx.y), min(tx.z, tHit));
    if (!(enter <= leave)) continue;  // NaN-safe: a NaN compares false
    uint first = floatBitsToUint(lo.w), count = floatBitsToUint(hi.w);
    if (count == 0u) {
      if (top < 62) { stack[top++] = first; stack[top++] = first + 1u; }
      continue;
    }
    for (uint i = first; i < first + count; ++i) {
      uint code = boundaryFaces[i];
      if (code == excluded) continue;  // the face the ray last entered through: no re-entry loop
      uint tet = code >> 2;
      int k = int(code & 3u);
      uvec4 tv = tets[tet];
      vec3 n, a;
      facePlane(tv, k, n, a);
      float den = dot(n, rayDir);
      if (den >= 0.0) continue;  // leaving through it, not entering
      float t = dot(n, a - rayOrigin) / den;
      if (t < tMin || t >= tHit) continue;
      // Inside the triangle, with a little slack so rays through shared edges are not lost.
      // (Barycentrics against the face's own winding: n may have been flipped outward.)
      vec3 p = rayOrigin + t * rayDir;
      vec3 p0 = nodes[tv[FACE[k].x]].xyz, p1 = nodes[tv[FACE[k].y]].xyz, p2 = nodes[tv[FACE[k].z]].xyz;
      vec3 w = cross(p1 - p0, p2 - p0);
      float area = dot(w, w);
      float u = dot(cross(p1 - p, p2 - p), w) / area, v = dot(cross(p2 - p, p0 - p), w) / area;
      float eps = 1e-5;
      if (u < -eps || v < -eps || u + v > 1.0 + eps) continue;
      best = int(tet);
      faceOut = k;
      tHit = t;
    }
  }
  return best;
}

void main() {
  ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
  if (pix.x >= imageSize_.x || pix.y >= imageSize_.y) return;
  vec2 ndc = vec2(2.0 * (float(pix.x) + 0.5) / float(imageSize_.x) - 1.0,
                  1.0 - 2.0 * (float(pix.y) + 0.5) / float(imageSize_.y));
  vec2 range = setupRay(ndc, pix);
  float t = range.x, tEnd = range.y;

  int steps = 0;
  uint lastEntry = 0xffffffffu;
  while (steps < maxSteps && accT >= terminationTransmittance) {
    float tIn;
    int face;
    int tet = findEntry(t, lastEntry, tIn, face);
    if (tet >= 0) lastEntry = uint(tet) * 4u + uint(face);
    if (tet < 0 || tIn > tEnd) break;
    // Walk until the ray leaves the mesh, then look for where it comes back.
    while (tet >= 0 && steps < maxSteps && accT >= terminationTransmittance) {
      ++steps;
      uvec4 tv = tets[tet];
      // Exit: the face the ray leaves through first, among those not behind the entry
      // point (rounding can put a face sharing the entry edge slightly behind it).
      float eps = 1e-5 * (abs(tIn) + length(nodes[tv.x].xyz - nodes[tv.y].xyz));
      float tOut = 3.4e38, tBehind = -3.4e38;
      int exitFace = -1, behindFace = -1;
      float tk[4];
      for (int k = 0; k < 4; ++k) {
        tk[k] = 3.4e38;
        if (k == face) continue;
        vec3 n, a;
        facePlane(tv, k, n, a);
        float den = dot(n, rayDir);
        if (den <= 0.0) continue;
        tk[k] = dot(n, a - rayOrigin) / den;
        if (tk[k] >= tIn - eps) {
          if (tk[k] < tOut) { tOut = tk[k]; exitFace = k; }  // ties: the lowest face index
        } else if (tk[k] > tBehind) {
          tBehind = tk[k];
          behindFace = k;
        }
      }
      // No segment through a tet is longer than its longest edge: a longer one means the
      // ray only grazes this tet (its true exit rounded to just behind the entry).
      vec3 q0 = nodes[tv.x].xyz, q1 = nodes[tv.y].xyz, q2 = nodes[tv.z].xyz, q3 = nodes[tv.w].xyz;
      float diameter = max(max(max(distance(q0, q1), distance(q0, q2)), max(distance(q0, q3), distance(q1, q2))),
                           max(distance(q1, q3), distance(q2, q3)));
      if (exitFace >= 0 && tOut - tIn > 1.001 * diameter + eps && behindFace >= 0) exitFace = -1;
      if (exitFace < 0) { exitFace = behindFace; tOut = tIn; }  // the ray only grazes this tet
      // A ray through an edge or vertex may tie a boundary face with an interior one: leaving
      // through the boundary there would skip the rest of the mesh, so take the interior one.
      if (exitFace >= 0 && neighbors[tet][exitFace] < 0) {
        for (int k = 0; k < 4; ++k)
          if (k != exitFace && tk[k] <= tOut + eps && tk[k] >= tIn - eps && neighbors[tet][k] >= 0) {
            exitFace = k;
            break;
          }
      }
      if (exitFace < 0) { t = tIn; break; }  // degenerate: search again from here
      tOut = max(tOut, tIn);  // a grazing exit (through the entry edge) has no length
      integrate(tv, uint(tet), tIn, min(tOut, tEnd));
      t = tOut;
      if (tOut >= tEnd) { tet = -1; steps = maxSteps; break; }
      int next = neighbors[tet][exitFace];
      if (next < 0) break;  // left the mesh
      // The face of `next` we came through is the one whose neighbour is `tet`.
      ivec4 nb = neighbors[next];
      face = nb.x == tet ? 0 : nb.y == tet ? 1 : nb.z == tet ? 2 : 3;
      tet = next;
      tIn = tOut;
    }
  }
  imageStore(outImage, pix, vec4(accColor, 1.0 - accT));
}
