// Empty-space skipping (visible_tets.comp finds the part): one bit per tet, set where the
// transfer function or an iso-surface can show something in it. With skipsHiddenTets the
// walk leaves the mesh where it would enter a hidden tet, and the entry search (whose BVH
// is then over the faces where the visible part ends) finds where it comes back.
layout(std430, binding = BINDING_VISIBLE_TETS) readonly buffer VisibleTets { uint visibleWords[]; };
uniform bool skipsHiddenTets;

bool tetHidden(int tet) {
  return skipsHiddenTets && ((visibleWords[uint(tet) >> 5] >> (uint(tet) & 31u)) & 1u) == 0u;
}
