#version 450 core
// Streamline tubes and arrow glyphs: triangles made on the CPU around the lines.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in float value;

uniform mat4 modelView;
uniform mat4 projection;

out vec3 vViewPosition;
out vec3 vModelPosition;
out vec3 vViewNormal;
out float vValue;

void main() {
  vec4 viewPos = modelView * vec4(position, 1.0);
  vViewPosition = viewPos.xyz;
  vModelPosition = position;
  vViewNormal = mat3(modelView) * normal;
  vValue = value;
  gl_Position = projection * viewPos;
}
