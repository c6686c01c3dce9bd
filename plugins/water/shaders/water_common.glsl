// The water effect's uniform block (set 0, binding 0) and texture bindings.
#ifndef SNELL_WATER_COMMON_GLSL
#define SNELL_WATER_COMMON_GLSL

layout(set = 0, binding = 0) uniform WaterBlock {
  mat4 view_proj;          // the main view (Vulkan clip, y flipped)
  mat4 refraction_inv_vp;  // inverse of the refraction pass's (possibly oblique) view-proj
  vec4 eye;                // xyz world eye
  vec4 plane;              // (0, 1, 0, -height)
  vec4 rect;               // xy centre (x, z), zw size (x, z)
  vec4 wave;               // x 1/wave_length, y wave_height, z distortion, w time
  vec4 wind;               // xy scroll of layer 1 (m/s), zw scroll of layer 2
  vec4 water_color;        // rgb, a color_blend
  vec4 absorption;         // rgb 1/m, a shore_softness
  vec4 light_dir;          // xyz direction the light travels, w specular_intensity
  vec4 light_color;        // rgb, a specular_power
  vec4 fresnel;            // x mode (0 exact, 1 schlick, 2 seed, 3 constant), y 1/ior, z f0, w debug
  vec4 extent;             // xy output size in pixels, zw 1/size
  vec4 side;               // x +1 eye above the water, -1 below; y ior; z reflectance
} water;

layout(set = 0, binding = 1) uniform sampler2D reflection_tex;
layout(set = 0, binding = 2) uniform sampler2D refraction_tex;
layout(set = 0, binding = 3) uniform sampler2D refraction_depth;
layout(set = 0, binding = 4) uniform sampler2D normal_map;

#endif
