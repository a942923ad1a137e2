// Clip planes for the host's geometry (surface, sections, streamlines, tubes): keep
// dot(n, p) + w >= -clipTolerance, in coordinates relative to the model center. A section
// lying on a plane passes its own plane by the tolerance.
uniform int clipCount;
uniform vec4 clipPlanes[MAX_CLIP_PLANES];  // volumeLimitDefines(): planes and box together
uniform float clipTolerance;

bool clippedAway(vec3 p) {
  for (int i = 0; i < clipCount; ++i)
    if (dot(clipPlanes[i].xyz, p) + clipPlanes[i].w < -clipTolerance) return true;
  return false;
}
