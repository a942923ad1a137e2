#version 450 core
// Streamlines as lit lines: points relative to the model center, the tangent and the
// scalar the line is colored by at each point.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 tangent;
layout(location = 2) in float value;

uniform mat4 modelView;

out vec3 gViewPosition;
out vec3 gModelPosition;
out vec3 gViewTangent;
out float gValue;

void main() {
  gModelPosition = position;
  gViewPosition = (modelView * vec4(position, 1.0)).xyz;
  gViewTangent = mat3(modelView) * tangent;  // rotation + translation: directions map by the 3x3 part
  gValue = value;
}
