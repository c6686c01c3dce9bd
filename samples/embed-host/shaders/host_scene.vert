#version 460
// The embed-host sample's geometry: world-space vertices with a normal and a colour, clipped
// against the view's world plane (gl_ClipDistance, needs shaderClipDistance).
#extension GL_GOOGLE_include_directive : require
#include "host_common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_color; // rgb: linear colour; a: tile contrast

layout(location = 0) out vec3 out_normal;
layout(location = 1) out vec4 out_color;
layout(location = 2) out vec3 out_world;

out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
};

void main() {
  vec4 world = vec4(in_position, 1.0);
  gl_Position = pc.matrix * world;
  gl_ClipDistance[0] = dot(pc.clip_plane, world);
  out_normal = in_normal;
  out_color = in_color;
  out_world = in_position;
}
