// Shared by the scene shaders: the per-view uniform block (set 0) and per-draw push constants.
#ifndef SNELL_SCENE_COMMON_GLSL
#define SNELL_SCENE_COMMON_GLSL

#include "snell/sky.glsl"

layout(set = 0, binding = 0) uniform ViewBlock {
  mat4 view_proj[6];     // one per view of a multiview pass; [0] otherwise
  mat4 inv_view_proj[6]; // for the sky's view directions
  vec4 eye;              // xyz world eye position
  vec4 clip_plane;       // world plane (n, d), keep dot >= 0; (0,0,0,1) = no clipping
  vec4 light_dir;        // xyz direction the light travels, w intensity
  vec4 light_color;      // rgb
  vec4 ambient;          // rgb
  vec4 sky_zenith;       // rgb
  vec4 sky_horizon;      // rgb
  vec4 sky_ground;       // rgb
} view_block;

layout(push_constant) uniform DrawBlock {
  mat4 model;
  vec4 base_color;
  vec4 emissive;         // rgb emissive, a = 1 if the base colour texture is used
  vec4 params;           // x roughness, y specular, z normal_scale, w alpha_cutoff (<0: opaque)
  vec4 flags;            // x has normal map, yz uv_scale, w unused
} draw;

vec3 sky_color(vec3 dir) {
  return sky_gradient(dir, view_block.sky_zenith.rgb, view_block.sky_horizon.rgb,
                      view_block.sky_ground.rgb);
}

#endif
