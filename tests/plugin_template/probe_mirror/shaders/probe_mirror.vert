#version 460
// The mirror quad (the toolkit's unit quad) placed by the model matrix.
layout(set = 0, binding = 0) uniform Block {
  mat4 view_proj;
  mat4 model;
  vec4 extent; // zw = 1 / output size
} block;
layout(location = 0) in vec3 in_position;
void main() {
  gl_Position = block.view_proj * block.model * vec4(in_position, 1.0);
}
