#version 450 core
// GPU ray marching through a regular grid, one invocation per pixel: the ray is cut to the
// grid's box and the clip planes, stepped on a lattice of marchStep along it (the same
// lattice wherever a ray starts, so the picture does not shimmer as the camera moves), the
// value at each step interpolated trilinearly from the 8 points around it, and each piece
// between two steps integrated with the scalar linear along it (common/volume_segment.glsl).
// A frame is one or more passes of at most stepsPerPass steps per ray: each pass resumes
// where the last stopped (its parameter and transmittance in resumeAt). Long loops in one
// invocation are what drivers cut short: llvmpipe ends every loop of an invocation after
// 65535 iterations in all, silently; a GPU's watchdog resets the device. A grid in bricks
// is marched brick by brick, front to back: each brick's passes march every ray's part
// inside that brick, going on from the color and transmittance the nearer bricks left.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform image2D outImage;    // premultiplied color, alpha
layout(rg32f, binding = 1) uniform image2D resumeAt;      // (t to resume at, or -1 when done; transmittance)
uniform bool firstPass;     // the brick's first pass: rays start where they enter it
uniform int stepsPerPass;
uniform ivec2 pixelOffset;  // the dispatch covers the pixels the brick can cover, from here
uniform ivec2 pixelEnd;     // to here (exclusive)
// Shading and 2D transfer functions read the gradient, which jumps across cell faces: the
// pieces are then also cut where the ray crosses a cell face and both ends of a piece take
// its own cell's polynomial, so the shading between them is second order in the step.
uniform bool cellCuts;

#include "common/volume_segment.glsl"

#include "common/grid_sampling.glsl"

void main() {
  ivec2 pix = ivec2(gl_GlobalInvocationID.xy) + pixelOffset;
  if (pix.x >= pixelEnd.x || pix.y >= pixelEnd.y) return;
  vec2 ndc = vec2(2.0 * (float(pix.x) + 0.5) / float(imageSize_.x) - 1.0,
                  1.0 - 2.0 * (float(pix.y) + 0.5) / float(imageSize_.y));
  // What the nearer bricks and passes left (the frame starts from a cleared image:
  // nothing, transmittance 1).
  vec2 resume = imageLoad(resumeAt, pix).xy;
  if (!firstPass && resume.x < 0.0) return;  // this ray is done in this brick
  float t = resume.x;
  accColor = imageLoad(outImage, pix).rgb;
  accT = resume.y;
  // The ray and its extent, the same numbers in every pass.
  vec2 range = setupRay(ndc, pix);
  rayIndexOrigin = (worldToIndex * vec4(rayOrigin, 1.0)).xyz;
  rayIndexDir = mat3(worldToIndex) * rayDir;
  float t0 = range.x, t1 = range.y;
  bool inside = insideGrid(t0, t1) && clipSegment(t0, t1);
  if (firstPass) t = inside ? t0 : t1;
  if (inside && t < t1) {
    vec4 front = sampleAlongRay(t);
    vec2 frontShade = shadeOf(front);
    for (int n = 0; n < stepsPerPass && t < t1 && accT >= terminationTransmittance; ++n) {
      float next = min((floor(t / marchStep) + 1.0) * marchStep, t1);
      if (next <= t) next = min(t + marchStep, t1);  // t beyond float's resolution of the lattice
      if (next <= t) { t = t1; break; }
      if (cellCuts) {
        next = min(next, nextCellFace(t));
        vec3 cell = cellOfIndex(rayIndexOrigin + (0.5 * (t + next)) * rayIndexDir);
        front = trilinearInCell(rayIndexOrigin + t * rayIndexDir, cell);
        frontShade = shadeOf(front);
      }
      vec4 back = cellCuts ? trilinearInCell(rayIndexOrigin + next * rayIndexDir,
                                             cellOfIndex(rayIndexOrigin + (0.5 * (t + next)) * rayIndexDir))
                           : sampleAlongRay(next);
      vec2 backShade = shadeOf(back);
      shadeFront = frontShade;
      shadeBack = backShade;
#if INTEGRATION_MODE == 4  // a 2D transfer function reads the gradient magnitude
      gradientFront = length(worldGradient(front.yzw));
      gradientBack = length(worldGradient(back.yzw));
#endif
      integrateValues(t, next, front.x, back.x);
      t = next;
      front = back;
      frontShade = backShade;
    }
  }
  bool done = !inside || !(t < t1) || !(accT >= terminationTransmittance);  // a NaN ends the ray too
  imageStore(resumeAt, pix, vec4(done ? -1.0 : t, accT, 0.0, 0.0));
  imageStore(outImage, pix, vec4(accColor, 1.0 - accT));
}
