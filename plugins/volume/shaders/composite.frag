#version 450 core
// The volume's premultiplied float image (its first row is the top) blended "over" what the
// target holds: one texel per pixel, or one per block of pixels when the image was computed
// at a reduced size (the CPU ray caster's quick frames while the view moves).
layout(binding = UNIT_IMAGE) uniform sampler2D image;
uniform vec2 viewportSize;
out vec4 fragColor;
void main() {
  ivec2 size = textureSize(image, 0);
  ivec2 p = min(ivec2(gl_FragCoord.xy * vec2(size) / viewportSize), size - 1);
  fragColor = texelFetch(image, ivec2(p.x, size.y - 1 - p.y), 0);
}
