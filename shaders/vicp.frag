#version 450 core
// One front face fragment of a tet: the ray through the pixel enters here; its exit is the
// nearest of the other faces; the segment is integrated exactly as the ray caster does
// (same code, common/tet_segment.glsl) and blended back to front over what is behind.
#include "common/tet_segment.glsl"

flat in uint vTet;
flat in int vFace;
out vec4 fragColor;

void main() {
  // The image is drawn y-flipped (its first row is the top): window row y is NDC 1 - 2y/h.
  vec2 ndc = vec2(2.0 * gl_FragCoord.x / float(imageSize_.x) - 1.0, 1.0 - 2.0 * gl_FragCoord.y / float(imageSize_.y));
  vec4 nearP = inverseViewProjection * vec4(ndc, -1.0, 1.0), farP = inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 nearPoint = nearP.xyz / nearP.w, farPoint = farP.xyz / farP.w;
  rayOrigin = orthographic ? nearPoint : eye;
  rayDir = normalize(farPoint - rayOrigin);
  uvec4 tv = tets[vTet];
  vec3 n, a;
  facePlane(tv, vFace, n, a);
  float den = dot(n, rayDir);
  if (den >= 0.0) discard;  // a back face: the tet is integrated from its front face
  float tIn = dot(n, a - rayOrigin) / den;
  float tOut = 3.4e38;
  for (int k = 0; k < 4; ++k) {
    if (k == vFace) continue;
    facePlane(tv, k, n, a);
    float d = dot(n, rayDir);
    if (d > 0.0) tOut = min(tOut, dot(n, a - rayOrigin) / d);
  }
  if (tOut == 3.4e38) discard;
  // As in the ray caster: no segment through a tet is longer than its longest edge. A
  // longer one means this pixel's ray only grazes the tet (a fragment on its silhouette):
  // its true length is zero.
  vec3 q0 = nodes[tv.x].xyz, q1 = nodes[tv.y].xyz, q2 = nodes[tv.z].xyz, q3 = nodes[tv.w].xyz;
  float diameter = max(max(max(distance(q0, q1), distance(q0, q2)), max(distance(q0, q3), distance(q1, q2))),
                       max(distance(q1, q3), distance(q2, q3)));
  if (tOut - tIn > 1.001 * diameter + 1e-5 * (abs(tIn) + diameter)) discard;
  tOut = max(tOut, tIn);
  float tStart = orthographic ? 0.0 : length(nearPoint - eye);
  tIn = max(tIn, tStart);
  if (hasSceneDepth) {  // opaque geometry in front of the exit ends the segment there
    float depth = texelFetch(sceneDepth, ivec2(int(gl_FragCoord.x), imageSize_.y - 1 - int(gl_FragCoord.y)), 0).r;
    if (depth < 1.0) {
      vec4 hit = inverseViewProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
      tOut = min(tOut, dot(hit.xyz / hit.w - rayOrigin, rayDir));
    }
  }
  if (tOut <= tIn) discard;
  integrate(tv, vTet, tIn, tOut);
  // Defensive: a tet flat in float32 has no defined barycentric values; its fragment must
  // not poison the image with NaN (the bench shows none since integrateLinear no longer
  // divides by a flushed-to-zero value difference).
  if (isnan(accT) || any(isnan(accColor))) discard;
  fragColor = vec4(accColor, 1.0 - accT);  // premultiplied
}
