// The tet across each face of a tet (raycast.comp's walk, visible_tets.comp): three words per tet holding four 24-bit fields, then the far
// pairs (TetMeshGpu::neighbors): 0 = boundary, 1 = far, else the index step to the tet
// across (bits 2..23, signed) and the face it is entered through (bits 0..1).
layout(std430, binding = BINDING_NEIGHBORS) readonly buffer Neighbors { uint neighborWords[]; };
uniform uint farNeighborBase;   // where the far pairs start in neighborWords (3 x tets)
uniform uint farNeighborCount;

// The packed field of tet `tet`'s face k.
uint neighborField(int tet, int k) {
  uint b = uint(tet) * 3u;
  if (k == 0) return neighborWords[b] & 0xffffffu;
  if (k == 1) return (neighborWords[b] >> 24) | ((neighborWords[b + 1u] & 0xffffu) << 8);
  if (k == 2) return (neighborWords[b + 1u] >> 16) | ((neighborWords[b + 2u] & 0xffu) << 16);
  return neighborWords[b + 2u] >> 8;
}

// The tet across face k of `tet` (-1: the boundary) and the face the ray enters it through.
int neighborAcross(int tet, int k, out int entryFace) {
  uint field = neighborField(tet, k);
  entryFace = int(field & 3u);
  if (field == 0u) return -1;
  if (field != 1u) return tet + (int(field << 8) >> 10);
  uint key = uint(tet) * 4u + uint(k), lo = 0u, hi = farNeighborCount;  // a far one: search its pair
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (neighborWords[farNeighborBase + 2u * mid] < key) lo = mid + 1u;
    else hi = mid;
  }
  uint target = neighborWords[farNeighborBase + 2u * lo + 1u];
  entryFace = int(target & 3u);
  return int(target >> 2);
}

