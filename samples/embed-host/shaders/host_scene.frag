#version 460
// Colour * (ambient + diffuse) with one directional light, deliberately simple, with 1 m tiles
// (a 3D checker, so refraction and reflection distortions are easy to see).
#extension GL_GOOGLE_include_directive : require
#include "host_common.glsl"

layout(location = 0) in vec3 in_normal;
layout(location = 1) in vec4 in_color;
layout(location = 2) in vec3 in_world;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 n = normalize(in_normal);
  // Cells of the checker just inside the surface, so faces on integer coordinates do not flicker.
  ivec3 cell = ivec3(floor(in_world - 0.01 * n));
  float tile = ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0 : 1.0 - in_color.a;
  float diffuse = max(dot(n, -normalize(pc.light_dir.xyz)), 0.0);
  out_color = vec4(in_color.rgb * tile * (pc.ambient.rgb + pc.light_color.rgb * diffuse), 1.0);
}
