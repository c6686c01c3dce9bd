#version 460
// Fullscreen triangle at the far plane (depth 1, drawn after the geometry with LESS_OR_EQUAL);
// the world direction of each pixel comes from the inverse view-projection.
#extension GL_GOOGLE_include_directive : require
#include "host_common.glsl"

layout(location = 0) out vec3 out_dir;

void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  gl_Position = vec4(p, 1.0, 1.0);
  vec4 far_point = pc.matrix * vec4(p, 1.0, 1.0);
  vec4 near_point = pc.matrix * vec4(p, 0.0, 1.0);
  out_dir = far_point.xyz * near_point.w - near_point.xyz * far_point.w;
}
