#version 460
// Scene vertex shader: world position, TBN, and the optional world clip plane.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_multiview : require
#include "scene_common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_tangent;
layout(location = 3) in vec2 in_uv;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec4 out_tangent;
layout(location = 3) out vec2 out_uv;

out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
};

void main() {
  vec4 world = draw.model * vec4(in_position, 1.0);
  mat3 normal_matrix = transpose(inverse(mat3(draw.model)));
  out_world = world.xyz;
  out_normal = normal_matrix * in_normal;
  out_tangent = vec4(mat3(draw.model) * in_tangent.xyz, in_tangent.w);
  out_uv = in_uv * draw.flags.yz;
  // Signed distance in world units: the clip plane keeps its positive side (seed 001's
  // IsReflected / IsRefracted passes, without oblique projection).
  gl_ClipDistance[0] = dot(view_block.clip_plane, vec4(world.xyz, 1.0));
  gl_Position = view_block.view_proj[gl_ViewIndex] * world;
}
