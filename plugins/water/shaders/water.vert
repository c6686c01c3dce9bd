#version 460
// The water rectangle: the toolkit's unit quad (Shape::quad, x and z in [-0.5, 0.5]) placed on
// the plane y = height over the rectangle of the uniform block.
#extension GL_GOOGLE_include_directive : require
#include "water_common.glsl"

layout(location = 0) in vec3 in_position; // snell::Vertex (the other attributes are unused)
layout(location = 0) out vec3 out_world;

void main() {
  vec2 xz = water.rect.xy + in_position.xz * water.rect.zw;
  vec3 world = vec3(xz.x, -water.plane.w, xz.y);
  out_world = world;
  gl_Position = water.view_proj * vec4(world, 1.0);
}
