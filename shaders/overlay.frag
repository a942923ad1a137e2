#version 450 core
in vec2 vUv;
uniform sampler2D image;
out vec4 fragColor;
void main() { fragColor = texture(image, vUv); }
