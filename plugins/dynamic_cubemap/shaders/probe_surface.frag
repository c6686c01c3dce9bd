#version 460
// The probe's owner shaded from its capture: mirror, refraction through a solid sphere, or both
// weighted by exact dielectric Fresnel (snell/probe.glsl).
#extension GL_GOOGLE_include_directive : require
#include "snell/probe.glsl"
#include "probe_common.glsl"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 v = normalize(in_world - probe_block.eye.xyz);
  vec3 n = normalize(in_normal);
  if (dot(n, v) > 0.0) {
    n = -n;
  }
  bool boxed = probe_block.tint.w > 0.5;
  int surface = int(probe_block.optics.x);
  float ior = probe_block.optics.y;
  float roughness = probe_block.optics.z;
  float levels = probe_block.optics.w;
  vec3 color;
  vec3 mirrored = reflect(v, n);
  if (boxed) {
    mirrored = probe_box_direction(in_world, mirrored, probe_block.center.xyz,
                                   probe_block.box_min.xyz, probe_block.box_max.xyz);
  }
  if (surface == 0) {
    color = probe_lookup(probe_cube, mirrored, roughness, levels);
  } else {
    vec3 through = probe_refract_sphere(probe_cube, v, n, ior, roughness, levels);
    if (surface == 1) {
      color = through;
    } else {
      float f = fresnel_dielectric(-dot(n, v), 1.0 / ior);
      color = mix(through, probe_lookup(probe_cube, mirrored, roughness, levels), f);
    }
  }
  out_color = vec4(color * probe_block.tint.rgb, 1.0);
}
