#version 450 core
// View-independent cell projection (Weiler et al. 2003): every tet is drawn as its four
// faces, pulled from the GPU-resident mesh in the order of the sorted index list (no
// geometry travels per frame, only the order). Fragments of back faces are discarded in
// vicp.frag, so each pixel a tet covers is integrated once, from its front face.
layout(std430, binding = 0) readonly buffer Nodes { vec4 nodes[]; };
layout(std430, binding = 1) readonly buffer Tets { uvec4 tets[]; };
layout(std430, binding = 8) readonly buffer Order { uint order[]; };
uniform mat4 viewProjection;  // mesh-relative -> clip, y flipped: row 0 of the image is the top

const ivec3 FACE[4] = ivec3[4](ivec3(1, 2, 3), ivec3(0, 2, 3), ivec3(0, 1, 3), ivec3(0, 1, 2));

flat out uint vTet;
flat out int vFace;

void main() {
  uint tet = order[gl_VertexID / 12];
  int face = (gl_VertexID % 12) / 3;
  uvec4 tv = tets[tet];
  vTet = tet;
  vFace = face;
  gl_Position = viewProjection * vec4(nodes[tv[FACE[face][gl_VertexID % 3]]].xyz, 1.0);
}
