#version 460
// The mirror's mesh (the node's, or the toolkit's unit quad placed as the rectangle).
#extension GL_GOOGLE_include_directive : require
#include "mirror_common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 3) in vec2 in_uv;
layout(location = 0) out vec3 out_world;
layout(location = 1) out vec2 out_uv;

void main() {
  vec4 world = mirror.model * vec4(in_position, 1.0);
  out_world = world.xyz;
  out_uv = in_uv;
  gl_Position = mirror.view_proj * world;
  // A node's mesh is also drawn by the scene renderer in the opaque pass at this very depth:
  // a hair nearer (1e-5 of w, far below what a scene resolves) so that LESS keeps the mirror.
  gl_Position.z -= 1e-5 * gl_Position.w;
}
