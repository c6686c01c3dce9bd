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
// above the plane, seen along a path of `path` m (eye to mirror to point), as a surface of
// `roughness` scatters it: a lobe of half-angle ~roughness^2 spreads it over 2 height
// roughness^2 m, which is that many pixels at `focal_px` pixels per unit of tan(angle) (the
// reflection target's height times proj[1][1] / 2). Contact hardening: 0 where it touches.
float mirror_blur_lod(float roughness, float height, float path, float focal_px, float levels) {
  float spread = 2.0 * height * roughness * roughness / max(path, 1e-4);
  float pixels = spread * focal_px;
  return clamp(log2(max(pixels, 1.0)), 0.0, max(levels - 1.0, 0.0));
}

#endif
