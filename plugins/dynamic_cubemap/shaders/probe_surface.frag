#version 460
// The probe's owner shaded from its capture: mirror, refraction through a solid sphere, or both
// weighted by exact dielectric Fresnel (snell/probe.glsl). The surface mode, box projection and
// dispersion are specialization constants: one pipeline per combination in use, because a CPU
// device (lavapipe) runs every branch of a shader and would pay for all three modes.
#extension GL_GOOGLE_include_directive : require
#include "snell/probe.glsl"
#include "probe_common.glsl"

layout(constant_id = 0) const uint kSurface = 0u;    // 0 reflect, 1 refract, 2 glass
layout(constant_id = 1) const bool kBoxed = false;   // box projection of the reflection
layout(constant_id = 2) const bool kDispersed = false; // per-channel IOR (refract, glass)

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_color;

vec3 through(vec3 v, vec3 n, float ior, float roughness, float levels) {
  if (!kDispersed) {
    return probe_refract_sphere(probe_cube, v, n, ior, roughness, levels);
  }
  vec3 iors = dispersion_iors(ior, probe_block.optics.x);
  return vec3(probe_refract_sphere(probe_cube, v, n, iors.r, roughness, levels).r,
              probe_refract_sphere(probe_cube, v, n, iors.g, roughness, levels).g,
              probe_refract_sphere(probe_cube, v, n, iors.b, roughness, levels).b);
}

void main() {
  vec3 v = normalize(in_world - probe_block.eye.xyz);
  vec3 n = normalize(in_normal);
  if (dot(n, v) > 0.0) {
    n = -n;
  }
  float ior = probe_block.optics.y;
  float roughness = probe_block.optics.z;
  float levels = probe_block.optics.w;
  vec3 color;
  if (kSurface == 1u) {
    color = through(v, n, ior, roughness, levels);
  } else {
    vec3 mirrored = reflect(v, n);
    if (kBoxed) {
      mirrored = probe_box_direction(in_world, mirrored, probe_block.center.xyz,
                                     probe_block.box_min.xyz, probe_block.box_max.xyz);
    }
    color = probe_lookup(probe_cube, mirrored, roughness, levels);
    if (kSurface == 2u) {
      float f = fresnel_dielectric(-dot(n, v), 1.0 / ior);
      color = mix(through(v, n, ior, roughness, levels), color, f);
    }
  }
  out_color = vec4(color * probe_block.tint.rgb, 1.0);
}
