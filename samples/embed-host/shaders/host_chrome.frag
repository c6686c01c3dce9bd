#version 460
// The host's chrome: a metal mirror shaded from Snell's probe (the dynamic_cubemap effect's
// published cube) with Snell's GLSL lookups, snell/probe.glsl (on the include path through
// snell_GLSL_INCLUDE_DIR). Schlick's Fresnel with the metal's coloured F0.
#extension GL_GOOGLE_include_directive : require
#include "host_chrome.glsl"
#include "snell/probe.glsl"

layout(location = 0) in vec3 in_normal;
layout(location = 1) in vec3 in_world;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 n = normalize(in_normal);
  vec3 view = normalize(in_world - pc.eye.xyz); // from the eye to the surface
  float roughness = chrome.f0_roughness.a;
  float levels = chrome.center_levels.w;
  vec3 seen;
  if (chrome.box_min.w > 0.5) {
    // Box projection: aim the lookup from the capture centre at where the reflected ray leaves
    // the probe's box (parallax correction for a room).
    vec3 dir = probe_box_direction(in_world, reflect(view, n), chrome.center_levels.xyz,
                                   chrome.box_min.xyz, chrome.box_max.xyz);
    seen = probe_lookup(probe_cube, dir, roughness, levels);
  } else {
    seen = probe_reflect(probe_cube, view, n, roughness, levels); // capture at infinity
  }
  vec3 f0 = chrome.f0_roughness.rgb;
  float cos_theta = clamp(dot(n, -view), 0.0, 1.0);
  vec3 fresnel = f0 + (1.0 - f0) * pow(1.0 - cos_theta, 5.0);
  out_color = vec4(fresnel * seen, 1.0);
}
