#version 460
// Fullscreen triangle at the far plane for the gradient sky (drawn last, depth test LEQUAL).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_multiview : require
#include "scene_common.glsl"

layout(location = 0) out vec3 out_dir;

void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  // Depth 1 in [0,1] (standard depth); the world direction comes from the inverse view-proj.
  gl_Position = vec4(p, 1.0, 1.0);
  vec4 far_point = view_block.inv_view_proj[gl_ViewIndex] * vec4(p, 1.0, 1.0);
  vec4 near_point = view_block.inv_view_proj[gl_ViewIndex] * vec4(p, 0.0, 1.0);
  out_dir = far_point.xyz * near_point.w - near_point.xyz * far_point.w;
}
