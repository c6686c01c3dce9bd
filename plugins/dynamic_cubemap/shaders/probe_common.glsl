// Shared by the probe surface shaders: the per-frame uniform block (std140 mirror of ProbeBlock
// in dynamic_cubemap.cpp) and the cube.
#ifndef PROBE_COMMON_GLSL
#define PROBE_COMMON_GLSL

layout(set = 0, binding = 0, std140) uniform ProbeBlock {
  mat4 view_proj; // the main view
  mat4 model;     // the owner's object to world
  vec4 eye;       // xyz world eye
  vec4 optics;    // x dispersion, y ior, z roughness, w mip levels
  vec4 tint;      // rgb
  vec4 center;    // xyz the capture's centre
  vec4 box_min;   // xyz
  vec4 box_max;   // xyz
} probe_block;

layout(set = 0, binding = 1) uniform samplerCube probe_cube;

#endif
