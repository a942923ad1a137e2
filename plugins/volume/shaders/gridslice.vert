#version 450 core
// View-aligned slices through a regular grid's box (the polygons are cut on the CPU, back
// to front): each vertex only moves to clip space; gridslice.frag integrates the slab.
layout(location = 0) in vec3 position;  // volume-relative
uniform mat4 viewProjection;            // volume-relative -> clip, y flipped: row 0 of the image is the top
uniform bool screenQuad;                // the entry pass: positions are already clip-space x, y
out vec3 slicePoint;

void main() {
  slicePoint = position;
  gl_Position = screenQuad ? vec4(position.xy, 0.0, 1.0) : viewProjection * vec4(position, 1.0);
}
