#version 460
// The water rectangle: four corners on the plane y = height, from the uniform block.
#extension GL_GOOGLE_include_directive : require
#include "water_common.glsl"

layout(location = 0) out vec3 out_world;

void main() {
  vec2 corner = vec2(gl_VertexIndex & 1, (gl_VertexIndex >> 1) & 1) - 0.5;
  vec2 xz = water.rect.xy + corner * water.rect.zw;
  vec3 world = vec3(xz.x, -water.plane.w, xz.y);
  out_world = world;
  gl_Position = water.view_proj * vec4(world, 1.0);
}
