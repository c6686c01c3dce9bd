#version 460
// The chrome object's vertices (the host's vertex buffer: position, normal, colour unused),
// clipped against the view's world plane like the rest of the scene.
#extension GL_GOOGLE_include_directive : require
#include "host_chrome.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

layout(location = 0) out vec3 out_normal;
layout(location = 1) out vec3 out_world;

out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
};

void main() {
  vec4 world = vec4(in_position, 1.0);
  gl_Position = pc.matrix * world;
  gl_ClipDistance[0] = dot(pc.clip_plane, world);
  out_normal = in_normal;
  out_world = in_position;
}
