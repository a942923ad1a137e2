#version 450 core
// One tet's contribution to one pixel: the interval where the pixel's ray is inside the
// tet, integrated exactly as the ray caster does (same code, common/tet_segment.glsl) and
// blended back to front over what is behind. The tet arrives as a screen rectangle
// (vicp.vert); pixels the ray misses are discarded here.
#include "common/tet_segment.glsl"

flat in uint vTet;
out vec4 fragColor;

// The faces of a positively oriented tet (v0 v1 v2 v3), each wound so that its normal
// points out: face k is opposite vertex k.
const ivec3 OUTWARD[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 3, 2), ivec3(0, 1, 3), ivec3(0, 2, 1));

vec2 ndc;  // this pixel's centre

// Direction in which the ray is nudged, for rays that lie exactly in a face's plane (see
// tetChord): perspective moves its direction, orthographic its origin, both toward a
// neighbouring screen position along a direction no mesh is likely to align a face with
// (not a pixel axis). Computed only for such rays, which are rare.
vec3 nudgeDirection() {
  vec2 nudged = ndc + vec2(1e-3, 0.318e-3);
  vec4 nearQ = inverseViewProjection * vec4(nudged, -1.0, 1.0), farQ = inverseViewProjection * vec4(nudged, 1.0, 1.0);
  return orthographic ? nearQ.xyz / nearQ.w - rayOrigin : normalize(farQ.xyz / farQ.w - eye) - rayDir;
}

// Where the ray is inside the tet: between the last face plane it enters and the first it
// leaves (the tet is convex). Each face's plane is computed from its vertices in ascending
// index order, so the two tets sharing a face get the same crossing parameter bit for bit
// and split the ray exactly there, whatever rounding did to it (a ray running nearly inside
// the face included): neighbours neither overlap nor leave a gap. A ray exactly in a plane
// is nudged sideways by an infinitesimal amount, the same for every plane, so that one
// side only keeps it. (Treating rays within a tolerance of a plane as lying in it made
// things worse: 1e-5 left 2.7e-3 errors on bar_hex8, none at all leaves 5.9e-6.)
// faceIn, faceOut: the faces whose planes give tIn and tOut (-1 where none does).
bool tetChord(uvec4 tv, out float tIn, out float tOut, out int faceIn, out int faceOut) {
  tIn = -3.4e38;
  tOut = 3.4e38;
  faceIn = faceOut = -1;
  for (int k = 0; k < 4; ++k) {
    uvec3 f = uvec3(tv[OUTWARD[k].x], tv[OUTWARD[k].y], tv[OUTWARD[k].z]);
    bool flip = false;  // sorting by an odd permutation turns the normal inward
    if (f.x > f.y) { f.xy = f.yx; flip = !flip; }
    if (f.y > f.z) { f.yz = f.zy; flip = !flip; }
    if (f.x > f.y) { f.xy = f.yx; flip = !flip; }
    precise vec3 a = nodes[f.x].xyz;
    precise vec3 n = cross(nodes[f.y].xyz - a, nodes[f.z].xyz - a);
    if (flip) n = -n;  // exact: both neighbours still see the same magnitudes
    precise float den = dot(n, rayDir);
    precise float h = dot(n, a - rayOrigin);  // inside where t * den <= h
    if (den == 0.0 && h == 0.0) {
      // The ray lies in the plane (an axis view with a row of pixel centres on a grid
      // plane): the nudged ray is inside iff it moves against the outward normal. (A plane
      // containing the ray cannot be perpendicular to the nudge as well.)
      float side = dot(n, nudgeDirection());
      if (side > 0.0 || (side == 0.0 && flip)) return false;
      continue;
    }
    if (den == 0.0) {  // parallel: inside or outside all along
      if (h < 0.0) return false;
      continue;
    }
    float t = h / den;
    if (den > 0.0) {
      if (t < tOut) { tOut = t; faceOut = k; }
    } else if (t > tIn) {
      tIn = t;
      faceIn = k;
    }
  }
  return tIn < tOut;
}

void main() {
  // The image is drawn y-flipped (its first row is the top): window row y is NDC 1 - 2y/h.
  ndc = vec2(2.0 * gl_FragCoord.x / float(imageSize_.x) - 1.0, 1.0 - 2.0 * gl_FragCoord.y / float(imageSize_.y));
  vec2 range = setupRay(ndc, ivec2(gl_FragCoord.xy));  // the image's rows count from the top here
  uvec4 tv = tets[vTet];
  float tIn, tOut;
  int faceIn, faceOut;
  if (!tetChord(tv, tIn, tOut, faceIn, faceOut)) discard;
  if (tIn < range.x) faceIn = -1;
  if (tOut > range.y) faceOut = -1;
  tIn = max(tIn, range.x);
  tOut = min(tOut, range.y);  // opaque geometry in front of the exit ends the segment there
  if (tOut <= tIn) discard;
  integrateSegment(cornersOf(tv), tv, vTet, tIn, tOut, faceIn, faceOut);
  // Defensive: a tet flat in float32 has no defined barycentric values; its fragment must
  // not poison the image with NaN.
  if (isnan(accT) || any(isnan(accColor))) discard;
  fragColor = vec4(accColor, 1.0 - accT);  // premultiplied
}
