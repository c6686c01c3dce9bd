#version 460
// The reflection, looked up where this pixel is on screen (the reflection pass renders the
// mirrored camera with the same projection, so screen position = reflection texture position).
layout(set = 0, binding = 0) uniform Block {
  mat4 view_proj;
  mat4 model;
  vec4 extent;
} block;
layout(set = 0, binding = 1) uniform sampler2D reflection;
layout(location = 0) out vec4 out_color;
void main() {
  out_color = vec4(textureLod(reflection, gl_FragCoord.xy * block.extent.zw, 0.0).rgb, 1.0);
}
