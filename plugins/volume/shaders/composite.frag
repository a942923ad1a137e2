#version 450 core
// The volume's premultiplied float image, one texel per pixel (its first row is the top),
// blended "over" what the target holds.
layout(binding = UNIT_IMAGE) uniform sampler2D image;
out vec4 fragColor;
void main() {
  ivec2 size = textureSize(image, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  fragColor = texelFetch(image, ivec2(p.x, size.y - 1 - p.y), 0);
}
