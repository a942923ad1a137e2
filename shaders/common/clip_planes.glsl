// Clip planes for the host's geometry (streamlines, tubes): keep dot(n, p) + w >= 0, in
// coordinates relative to the model center.
uniform int clipCount;
uniform vec4 clipPlanes[8];

bool clippedAway(vec3 p) {
  for (int i = 0; i < clipCount; ++i)
    if (dot(clipPlanes[i].xyz, p) + clipPlanes[i].w < 0.0) return true;
  return false;
}
