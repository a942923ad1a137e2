#version 450 core
// Empty-space skipping for the tet renderers: the part of the mesh the transfer function
// and the iso-surfaces can show, found after each change of them (or of the values).
// Stage 0: a bit per tet that can show something (common/tet_segment.glsl's
// tetShowsNothing, the very test the renderers integrate with). Stage 1: the faces where
// that part ends (a visible tet's face on the boundary or against a hidden tet), listed
// with their corners for the BVH the host builds over them, as many as fit `capacity`
// (foundFaces counts them all: the host grows the list and runs stage 1 again if needed).
layout(local_size_x = 64) in;
layout(std430, binding = BINDING_VISIBLE_TETS) buffer VisibleTets { uint visibleWords[]; };
layout(std430, binding = BINDING_FOUND_FACES) buffer FoundFaces {
  uint foundFaces;
  uint visibleTets;
  uint unused[2];
  uvec4 found[];  // (tet * 4 + face, its three corners)
};
uniform uint tetCount;
uniform uint capacity;
uniform int stage;

#include "common/tet_segment.glsl"
#include "common/tet_neighbors.glsl"

bool visible(int tet) { return ((visibleWords[uint(tet) >> 5] >> (uint(tet) & 31u)) & 1u) != 0u; }

void main() {
  // Two-dimensional dispatch: a 1D one is limited to 65535 groups (4M tets) on some devices.
  uint t = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
  if (t >= tetCount) return;
  uvec4 tv = tets[t];
  if (stage == 0) {
    if (!tetShowsNothing(cornersOf(tv), t)) {
      atomicOr(visibleWords[t >> 5], 1u << (t & 31u));
      atomicAdd(visibleTets, 1u);
    }
    return;
  }
  if (!visible(int(t))) return;
  for (int k = 0; k < 4; ++k) {
    int entry;
    int across = neighborAcross(int(t), k, entry);
    if (across >= 0 && visible(across)) continue;
    uint slot = atomicAdd(foundFaces, 1u);
    if (slot < capacity) found[slot] = uvec4(t * 4u + uint(k), tv[FACE[k].x], tv[FACE[k].y], tv[FACE[k].z]);
  }
}
