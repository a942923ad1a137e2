#version 450 core
// One boundary face at one pixel: where the pixel's ray enters through it (the ray caster's
// own test, common/boundary_entry.glsl), as (t, face code), of which the depth test keeps
// the nearest; the farthest entry's parameter goes to an image by an atomic maximum (this
// shader writes the depth, so it runs for every fragment: one pass for both). The ray
// caster starts its rays at the nearest instead of searching its BVH, and searches for a
// re-entry only where an entry lies beyond the point a ray left.
#include "common/tet_segment.glsl"
#include "common/boundary_entry.glsl"

flat in uint vFace;
layout(location = 0) out uvec2 entry;  // the parameter's bits, the face code
// The farthest entry's parameter (its bits: parameters are >= 0 here, so their bits order
// as they do), cleared to 0.
layout(binding = 1, r32ui) uniform coherent uimage2D farthestEntry;

void main() {
  ivec2 pix = ivec2(gl_FragCoord.xy);  // drawn y-flipped: row 0 is the image's top, as in raycast.comp
  vec2 range = setupRay(pixelNdc(pix), pix);
  float t;
  if (!entersThrough(vFace, range.x, 3.4e38, t)) discard;
  imageAtomicMax(farthestEntry, pix, floatBitsToUint(max(t, 0.0)));
  gl_FragDepth = clamp((t - range.x) / max(range.y - range.x, 1e-30), 0.0, 1.0);
  entry = uvec2(floatBitsToUint(t), vFace);
}
