#version 460
// The sky. With a clip plane, directions leaving toward the clipped side are discarded: the sky
// is at infinity, so only the direction's side of the plane decides.
#extension GL_GOOGLE_include_directive : require
#include "host_common.glsl"

layout(location = 0) in vec3 in_dir;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 dir = normalize(in_dir);
  if (dot(pc.clip_plane.xyz, dir) < 0.0) {
    discard;
  }
  out_color = vec4(host_sky(dir), 1.0);
}
