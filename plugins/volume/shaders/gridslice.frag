#version 450 core
// One fragment of a view-aligned slice or of where rays enter the grid. The rays' parts
// inside the grid's box (and the clip planes, before the opaque scene) are partitioned
// exactly: a slice's fragment integrates its ray from the slice to the next slice behind
// (or to where the ray leaves), an entry fragment (one per pixel, from a quad over the whole
// picture) from where the ray enters to the first slice. Slices are drawn a little larger
// than the box's cut and fragments off the ray's part in the box discard themselves, so
// the rasterizer's coverage at the box's edges decides nothing. Each
// part is integrated with the scalar linear along it (common/volume_segment.glsl) and
// blended back to front ("over", premultiplied): slices farthest first, entries last.
// With the eye close to or inside the grid the slices are spherical shells round the eye
// instead (a quad over the brick's part of the picture per shell): every ray is then cut at
// the same distances from the eye, however oblique.
in vec3 slicePoint;
out vec4 fragColor;

#include "common/volume_segment.glsl"
#include "common/grid_sampling.glsl"

uniform vec3 viewDir;        // unit, toward the scene
uniform vec3 sliceEye;       // volume-relative: slice depths count from here along viewDir
uniform float sliceSpacing;  // along viewDir, model units: slices at depths k * sliceSpacing
uniform bool entryPass;      // drawing the entry geometry rather than slices
uniform bool shellPass;      // spherical shells round the eye: slicePoint.z is the shell's number k

void main() {
  vec2 ndc = vec2(2.0 * gl_FragCoord.x / float(imageSize_.x) - 1.0, 1.0 - 2.0 * gl_FragCoord.y / float(imageSize_.y));
  vec2 range = setupRay(ndc, ivec2(gl_FragCoord.xy));  // the image's rows count from the top here
  rayIndexOrigin = (worldToIndex * vec4(rayOrigin, 1.0)).xyz;
  rayIndexDir = mat3(worldToIndex) * rayDir;
  float tIn = range.x, tOut = range.y;
  if (!insideGrid(tIn, tOut) || !clipSegment(tIn, tOut)) discard;
  float cosine = max(dot(rayDir, viewDir), 1e-6);  // depth gained per unit of ray
  float a, b;
  if (shellPass) {
    // The shell between distances k and k + 1 spacings from the eye (rays start at the eye
    // and are of unit length): the shells partition every ray, no entry part is left.
    float k = slicePoint.z;
    a = max(k * sliceSpacing, tIn);
    b = min((k + 1.0) * sliceSpacing, tOut);
  } else if (entryPass) {
    float depthIn = dot(rayOrigin + tIn * rayDir - sliceEye, viewDir);
    float firstSlice = (floor(depthIn / sliceSpacing) + 1.0) * sliceSpacing;
    a = tIn;
    b = min(tIn + (firstSlice - depthIn) / cosine, tOut);
  } else {
    float here = dot(slicePoint - rayOrigin, rayDir);
    if (here <= tIn || here > tOut) discard;  // the entry's part, or beyond the ray's end
    a = here;
    b = min(here + sliceSpacing / cosine, tOut);
  }
  if (!(b > a)) discard;
  vec4 front = sampleAlongRay(a), back = sampleAlongRay(b);
  shadeFront = shadeOf(front);
  shadeBack = shadeOf(back);
#if INTEGRATION_MODE == 4  // a 2D transfer function reads the gradient magnitude
  gradientFront = length(worldGradient(front.yzw));
  gradientBack = length(worldGradient(back.yzw));
#endif
  integrateValues(a, b, front.x, back.x);
  fragColor = vec4(accColor, 1.0 - accT);
}
