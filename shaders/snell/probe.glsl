// Snell host shading: lookups into a probe's cube map (the dynamic_cubemap effect), for the
// effect's own surface and for a host's materials. Directions are world space; the cube is
// Vulkan's (face order +X -X +Y -Y +Z -Z, snell::direction_to_cube).
#ifndef SNELL_PROBE_GLSL
#define SNELL_PROBE_GLSL

#include "snell/optics.glsl"

// The capture along `dir`, blurred by `roughness` in [0, 1] (a fraction of the `levels` mip
// levels of the cube).
vec3 probe_lookup(samplerCube probe, vec3 dir, float roughness, float levels) {
  return textureLod(probe, dir, roughness * max(levels - 1.0, 0.0)).rgb;
}

// Box projection (parallax correction): the capture taken at `center` is the inside of the box
// box_min..box_max (a room). The ray from the surface point `pos` along `dir` leaves the box at
// pos + t dir, t the nearest exit over the three slabs; the lookup is aimed from the centre at
// that point. Exact for what lies on the box's walls; `pos` must be inside the box.
vec3 probe_box_direction(vec3 pos, vec3 dir, vec3 center, vec3 box_min, vec3 box_max) {
  vec3 to_max = (box_max - pos) / dir;
  vec3 to_min = (box_min - pos) / dir;
  vec3 exits = max(to_max, to_min);
  float t = min(min(exits.x, exits.y), exits.z);
  return pos + dir * t - center;
}

// Mirror reflection of the unit view ray `view` at the unit normal `normal`.
vec3 probe_reflect(samplerCube probe, vec3 view, vec3 normal, float roughness, float levels) {
  return probe_lookup(probe, reflect(view, normal), roughness, levels);
}

// Through a solid sphere of index `ior` entered at the unit normal `normal` (facing the ray):
// refracted in, across the chord 2 r cos(theta_t), and out at the far side. No total internal reflection can
// happen inside a sphere (the ray meets the far side at theta_t). The capture is treated as
// infinitely far away, so only the leaving direction matters.
vec3 probe_refract_sphere(samplerCube probe, vec3 view, vec3 normal, float ior, float roughness,
                          float levels) {
  vec3 inside;
  if (!refract(view, normal, 1.0 / ior, inside)) {
    return probe_lookup(probe, reflect(view, normal), roughness, levels);
  }
  // The far-side normal (outward): with the centre c and entry point p = c + r n, the ray
  // leaves at q = p + 2 r cos(theta_t) t, so (q - c) / r = n - 2 dot(n, t) t = reflect(n, t).
  vec3 far_normal = reflect(normal, inside);
  vec3 leaving;
  if (!refract(inside, -far_normal, ior, leaving)) {
    leaving = inside;
  }
  return probe_lookup(probe, leaving, roughness, levels);
}

#endif
