#version 460
// The probe's owner (its sphere or a scene object), placed by the block's model matrix.
#extension GL_GOOGLE_include_directive : require
#include "probe_common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;

void main() {
  vec4 world = probe_block.model * vec4(in_position, 1.0);
  out_world = world.xyz;
  out_normal = transpose(inverse(mat3(probe_block.model))) * in_normal;
  gl_Position = probe_block.view_proj * world;
}
