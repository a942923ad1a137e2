#version 450 core
// GPU ray casting through tetrahedra, one invocation per pixel: enter at a boundary face
// (found in a BVH over boundary faces, which also finds where a ray re-enters a
// non-convex mesh), walk tet to tet through face adjacency, leave each tet through the
// face the signs of the ray's Plucker products with its edges name (shared bit for bit
// with the neighbour), integrate each segment (four modes), composite front to back, stop
// early when nearly opaque.
//
// A dispatch takes each ray at most `stepsPerPass` tets further and stores where it
// stopped (rayState) next to its color so far (the image): the host dispatches again
// while rays are left unfinished. That bounds the work of one dispatch (a GPU's watchdog
// resets the device after a few seconds of one; the window slices a long frame into short
// dispatches to stay responsive) and every loop's iteration count (llvmpipe documents an
// iteration limit for shader loops; its tet walk here was measured right at 300000 tets in
// one dispatch, but its grid march was not, docs/user/seismic.md).
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform image2D outImage;
layout(std430, binding = BINDING_BVH) readonly buffer Bvh { vec4 bvh[]; };
layout(std430, binding = BINDING_BOUNDARY_FACES) readonly buffer BoundaryFaces { uint boundaryFaces[]; };
// Per pixel: x = phase (bits 0-1) | face entered (bits 2-3) | steps taken (bits 4-31);
// y = tet being crossed; z = the boundary face last entered through (tet * 4 + face);
// w = the ray parameter reached (float bits). A cleared buffer (all 0) means "not started".
// Where the device's storage blocks cannot hold a state per pixel, the image goes in bands of rows.
layout(std430, binding = BINDING_RAY_STATE) buffer RayState { uvec4 rayState[]; };
layout(std430, binding = BINDING_RAY_COUNTERS) buffer RayCounters {
  uint unfinishedRays;  // stopped at the end of this pass' share: dispatch again
  uint cappedRays;      // stopped at maxSteps: lost in a cycle of a broken mesh, or longer than allowed
};
uniform int maxSteps;      // for the whole ray
uniform int stepsPerPass;  // this dispatch's share of them
uniform ivec2 band;        // the rows this dispatch covers (first, count); rayState holds them only
uniform float reentryTolerance;  // a millionth of the mesh's diagonal
const uint PHASE_FRESH = 0u, PHASE_WALKING = 1u, PHASE_SEEKING = 2u, PHASE_DONE = 3u;

#include "common/tet_segment.glsl"
#include "common/tet_neighbors.glsl"
#include "common/hidden_tets.glsl"
#include "common/boundary_entry.glsl"

// The product as computed from the lower id to the higher (what both tets of a face share).
float fromLowerId(uint p, uint q, float product) { return p < q ? product : -product; }

// The exit face's three edge products, carried into the tet across, where that face is the
// entry face: the next step computes only the three edges to its fourth vertex, and the two
// tets of a face decide with the very same numbers. ids: the face's vertices; lowerFirst[i]:
// the product of the edge that leaves out ids[i], from its lower id to its higher.
struct CarriedFace {
  bool valid;
  uvec3 ids;
  vec3 lowerFirst;
};

// The product p -> q of an edge of the carried face.
float carriedProduct(CarriedFace c, uint p, uint q) {
  uint other = c.ids.x + c.ids.y + c.ids.z - p - q;  // the face's vertex not on the edge
  float v = other == c.ids.x ? c.lowerFirst.x : other == c.ids.y ? c.lowerFirst.y : c.lowerFirst.z;
  return p < q ? v : -v;
}

// The face (its index in the tet, opposite that vertex) a ray entered through face `entry`
// leaves by: with the entry face's vertices a, b, c (in FACE order) and the fourth vertex k,
// the ray leaves through the face opposite a when k->b turns like the entry face and k->c
// the other way, and so on round. Float signs that name no face (only in near-degenerate
// tets) give the face the ray misses by the least.
int exitFaceOf(uvec4 tv, mat4 P, int entry, inout CarriedFace carried) {
  ivec3 f = FACE[entry];
  uint A = tv[f.x], B = tv[f.y], C = tv[f.z], K = tv[entry];
  vec3 pA = P[f.x].xyz, pB = P[f.y].xyz, pC = P[f.z].xyz, pK = P[entry].xyz;
  float pAB, pBC, pCA;
  if (carried.valid) {
    pAB = carriedProduct(carried, A, B);
    pBC = carriedProduct(carried, B, C);
    pCA = carriedProduct(carried, C, A);
  } else {
    pAB = edgeProduct(A, B, pA, pB);
    pBC = edgeProduct(B, C, pB, pC);
    pCA = edgeProduct(C, A, pC, pA);
  }
  int votes = int(pAB > 0.0) + int(pBC > 0.0) + int(pCA > 0.0);
  float s = votes >= 2 ? 1.0 : -1.0;  // how the entry face turns around the ray
  float kA = edgeProduct(K, A, pK, pA), kB = edgeProduct(K, B, pK, pB), kC = edgeProduct(K, C, pK, pC);
  float eA = s * kA, eB = s * kB, eC = s * kC;
  int exitFace;
  if (eB > 0.0 && eC < 0.0) exitFace = f.x;
  else if (eC > 0.0 && eA < 0.0) exitFace = f.y;
  else if (eA > 0.0 && eB < 0.0) exitFace = f.z;
  else {
    float m0 = min(eB, -eC), m1 = min(eC, -eA), m2 = min(eA, -eB);
    exitFace = m0 >= m1 && m0 >= m2 ? f.x : (m1 >= m2 ? f.y : f.z);
  }
  carried.valid = true;
  if (exitFace == f.x) {
    carried.ids = uvec3(B, C, K);
    carried.lowerFirst = vec3(fromLowerId(K, C, kC), fromLowerId(K, B, kB), fromLowerId(B, C, pBC));
  } else if (exitFace == f.y) {
    carried.ids = uvec3(A, C, K);
    carried.lowerFirst = vec3(fromLowerId(K, C, kC), fromLowerId(K, A, kA), fromLowerId(C, A, pCA));
  } else {
    carried.ids = uvec3(A, B, K);
    carried.lowerFirst = vec3(fromLowerId(K, B, kB), fromLowerId(K, A, kA), fromLowerId(A, B, pAB));
  }
  return exitFace;
}

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
    if (count == 0u) {  // the nearer child on top: its hits shorten the search of the other
      if (top < 62) {
        vec3 a0 = (bvh[2u * first].xyz - rayOrigin) * inv, a1 = (bvh[2u * first + 1u].xyz - rayOrigin) * inv;
        vec3 b0 = (bvh[2u * first + 2u].xyz - rayOrigin) * inv, b1 = (bvh[2u * first + 3u].xyz - rayOrigin) * inv;
        vec3 an = min(a0, a1), bn = min(b0, b1);
        bool secondNearer = max(max(bn.x, bn.y), bn.z) < max(max(an.x, an.y), an.z);
        stack[top++] = secondNearer ? first : first + 1u;
        stack[top++] = secondNearer ? first + 1u : first;
      }
      continue;
    }
    for (uint i = first; i < first + count; ++i) {
      uint code = boundaryFaces[i];
      if (code == excluded) continue;  // the face the ray last entered through: no re-entry loop
      float t;
      if (!entersThrough(code, tMin, tHit, t)) continue;
      best = int(code >> 2);
      faceOut = int(code & 3u);
      tHit = t;
    }
  }
  return best;
}

// ---- the entry maps (TetRayDispatch::drawEntryMaps) -------------------------------------
// Per pixel, the nearest entry of its ray (the parameter's bits, the face code; 0xffffffff:
// none) and the farthest entry's parameter (0 where none), drawn before the frame with the
// same test (entry_faces.frag).
uniform bool hasEntryMaps;
layout(binding = UNIT_NEAREST_ENTRY) uniform usampler2D nearestEntry;
layout(binding = UNIT_FARTHEST_ENTRY) uniform usampler2D farthestEntry;

// Where a fresh ray first enters: the face the map names, checked with this ray (the map's
// fragment traced the same ray, so it holds; the BVH decides where it would not), or no
// entry at all where the map has none; without maps, the BVH.
int firstEntry(ivec2 pix, float tMin, out float tIn, out int faceOut) {
  if (!hasEntryMaps) return findEntry(tMin, 0xffffffffu, tIn, faceOut);
  uint code = texelFetch(nearestEntry, pix, 0).y;
  tIn = 3.4e38;
  faceOut = 0;
  if (code == 0xffffffffu) return -1;
  float t;
  if (!entersThrough(code, tMin, 3.4e38, t)) return findEntry(tMin, 0xffffffffu, tIn, faceOut);
  tIn = t;
  faceOut = int(code & 3u);
  return int(code >> 2);
}

// True when the ray's farthest entry lies before tFrom (by more than the re-entry
// tolerance, which covers any rounding between the map's parameter and the search's): no
// search for a re-entry can find one.
bool noEntryFrom(ivec2 pix, float tFrom) {
  if (!hasEntryMaps) return false;
  return uintBitsToFloat(texelFetch(farthestEntry, pix, 0).x) + reentryTolerance < tFrom;
}

void main() {
  ivec2 pix = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, band.x);
  if (pix.x >= imageSize_.x || pix.y >= min(imageSize_.y, band.x + band.y)) return;
  uint index = uint(pix.y - band.x) * uint(imageSize_.x) + uint(pix.x);
  uvec4 state = rayState[index];
  uint phase = state.x & 3u;
  if (phase == PHASE_DONE) return;
  vec2 range = setupRay(pixelNdc(pix), pix);  // the same ray in every pass
  float t = range.x, tEnd = range.y;
  int steps = 0;
  uint lastEntry = 0xffffffffu;
  int tet = -1, face = 0;
  CarriedFace carried;
  carried.valid = false;
  float tEntered = -3.4e38;  // where the ray last entered (unknown when a pass resumes)
  if (phase != PHASE_FRESH) {  // carry on where the last pass stopped
    vec4 sofar = imageLoad(outImage, pix);  // an unfinished ray's pixel holds its transmittance
    accColor = sofar.rgb;
    accT = sofar.a;
    face = int((state.x >> 2) & 3u);
    steps = int(state.x >> 4);
    tet = phase == PHASE_WALKING ? int(state.y) : -1;
    lastEntry = state.z;
    t = uintBitsToFloat(state.w);
  }
  int passEnd = min(maxSteps, steps + stepsPerPass);
  bool finished = false;
  while (!finished && steps < passEnd && accT >= terminationTransmittance) {
    if (tet < 0) {  // outside the mesh: where does the ray enter (again)?
      float tIn;
      tet = phase == PHASE_FRESH && steps == 0 ? firstEntry(pix, t, tIn, face) : findEntry(t, lastEntry, tIn, face);
      if (tet < 0 || tIn > tEnd) { finished = true; break; }
      lastEntry = uint(tet) * 4u + uint(face);
      t = tIn;
      tEntered = tIn;
      carried.valid = false;
    }
    // Walk until the ray leaves the mesh, then look for where it comes back.
    while (steps < passEnd && accT >= terminationTransmittance) {
      ++steps;
      uvec4 tv = tets[tet];
      mat4 P = cornersOf(tv);
      int exitFace = exitFaceOf(tv, P, face, carried);
      // Where it leaves: the exit face's plane, kept within the tet's extent along the ray
      // (a ray running in the face's plane may cross it anywhere along the face).
      // (One square root of the longest squared edge: the same number as the longest edge.)
      vec3 e01 = P[1].xyz - P[0].xyz, e02 = P[2].xyz - P[0].xyz, e03 = P[3].xyz - P[0].xyz;
      vec3 e12 = P[2].xyz - P[1].xyz, e13 = P[3].xyz - P[1].xyz, e23 = P[3].xyz - P[2].xyz;
      float diameter = sqrt(max(max(max(dot(e01, e01), dot(e02, e02)), max(dot(e03, e03), dot(e12, e12))),
                                max(dot(e13, e13), dot(e23, e23))));
      vec3 n, a;
      facePlane(P, exitFace, n, a);
      float den = dot(n, rayDir);
      float onPlane = den > 0.0 ? dot(n, a - rayOrigin) / den : t;
      float tOut = clamp(onPlane, t, t + 1.001 * diameter);
      integrateSegment(P, tv, uint(tet), t, min(tOut, tEnd), face, tOut == onPlane && tOut <= tEnd ? exitFace : -1);
      t = tOut;
      if (tOut >= tEnd) { finished = true; break; }
      int entry;
      int next = neighborAcross(tet, exitFace, entry);
      if (next < 0 || tetHidden(next)) {  // left the mesh, or the part that shows
        // Search again from a little before the exit: where the ray leaves through an edge
        // or a vertex into a tet it only touches there, that tet's face is crossed at the
        // same point, computed from another plane (the CPU ray caster's tolerance). Never
        // before the last entry: that part is walked already.
        t = max(tOut - reentryTolerance, tEntered);
        tet = -1;
        if (noEntryFrom(pix, t)) finished = true;
        break;
      }
      face = entry;
      tet = next;
    }
  }
  // Opaque enough, or not a number (a NaN would otherwise leave the ray unfinished for ever
  // and the host dispatching again without end).
  if (!(accT >= terminationTransmittance)) finished = true;
  if (!finished && steps >= maxSteps) {
    atomicAdd(cappedRays, 1u);
    finished = true;
  }
  if (finished) {
    imageStore(outImage, pix, vec4(accColor, 1.0 - accT));
    rayState[index].x = PHASE_DONE;
    return;
  }
  // Unfinished: the transmittance itself, so the next pass goes on with the very same
  // number (1 - (1 - T) is not T in floats) and a sliced frame equals an unsliced one.
  imageStore(outImage, pix, vec4(accColor, accT));
  atomicAdd(unfinishedRays, 1u);
  phase = tet >= 0 ? PHASE_WALKING : PHASE_SEEKING;
  rayState[index] = uvec4(phase | (uint(face) << 2) | (uint(steps) << 4), uint(max(tet, 0)), lastEntry, floatBitsToUint(t));
}
