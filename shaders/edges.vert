#version 450 core
layout(location = 0) in vec3 position;
uniform mat4 modelView;
uniform mat4 projection;
out vec3 vModelPosition;  // relative to the model center, for the clip planes
void main() {
  vModelPosition = position;
  gl_Position = projection * modelView * vec4(position, 1.0);
}
