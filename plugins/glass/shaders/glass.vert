#version 460
// A transmissive surface: snell::Vertex in object space, placed by the push constants' model
// matrix (the pane: the toolkit's unit quad on the slab's face nearest the eye).
#extension GL_GOOGLE_include_directive : require
#include "glass_common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_tangent;
layout(location = 3) in vec2 in_uv;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_uv;

void main() {
  vec4 world = draw.model * vec4(in_position, 1.0);
  out_world = world.xyz;
  // Normals transform with the inverse transpose (non-uniform scale keeps them perpendicular).
  out_normal = transpose(inverse(mat3(draw.model))) * in_normal;
  out_uv = in_uv;
  gl_Position = glass.view_proj * world;
}
