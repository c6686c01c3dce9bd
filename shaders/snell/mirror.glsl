// Snell host shading: lookups into a planar mirror's reflection (the mirror effect), for the
// effect's own surface and for a host's materials (snell::MirrorHostView gives the image, the
// sampler and the texture matrix).
#ifndef SNELL_MIRROR_GLSL
#define SNELL_MIRROR_GLSL

// The reflection's uv of world point `world` through `texture_matrix` (MirrorHostView): on the
// mirror's plane, the pixel of the main view it is seen at.
vec2 mirror_uv(mat4 texture_matrix, vec3 world) {
  vec4 t = texture_matrix * vec4(world, 1.0);
  return t.xy / t.w;
}

// The level of a reflection of `levels` mips that blurs a reflected point standing `height` m
// above the plane, seen from `eye_distance` m away (eye to the mirror point), as a surface of
// `roughness` scatters it: a lobe of half-angle ~roughness^2 spreads it over 2 height
// roughness^2 m, seen from the eye across eye_distance + height, so over an angle of
// 2 roughness^2 height / (eye_distance + height) (2 roughness^2 for what is infinitely far),
// which is that many pixels at `focal_px` pixels per unit of tan(angle) (the reflection
// target's height times proj[1][1] / 2). Contact hardening: level 0 where it touches.
float mirror_blur_lod(float roughness, float height, float eye_distance, float focal_px,
                      float levels) {
  float h = min(height, 1e6);
  float angle = 2.0 * roughness * roughness * h / max(eye_distance + h, 1e-4);
  return clamp(log2(max(angle * focal_px, 1.0)), 0.0, max(levels - 1.0, 0.0));
}

#endif
