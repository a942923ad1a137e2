#version 450 core
// One boundary face at one pixel: where the pixel's ray enters through it (the ray caster's
// own test, common/boundary_entry.glsl), as (t, face code); the depth test keeps the
// nearest entry (or the farthest, with the depth test reversed). The ray caster starts its
// rays at the nearest instead of searching its BVH, and searches for a re-entry only where
// an entry lies beyond the point a ray left.
#include "common/tet_segment.glsl"
#include "common/boundary_entry.glsl"

flat in uint vFace;
layout(location = 0) out uvec2 entry;  // the parameter's bits, the face code

void main() {
  ivec2 pix = ivec2(gl_FragCoord.xy);  // drawn y-flipped: row 0 is the image's top, as in raycast.comp
  vec2 range = setupRay(pixelNdc(pix), pix);
  float t;
  if (!entersThrough(vFace, range.x, 3.4e38, t)) discard;
  gl_FragDepth = clamp((t - range.x) / max(range.y - range.x, 1e-30), 0.0, 1.0);
  entry = uvec2(floatBitsToUint(t), vFace);
}
