// Shared by the mirror shaders: the per-frame uniform block (std140 mirror of MirrorBlock in
// mirror.cpp) and the images.
#ifndef MIRROR_COMMON_GLSL
#define MIRROR_COMMON_GLSL

layout(set = 0, binding = 0, std140) uniform MirrorBlock {
  mat4 view_proj;         // the main view
  mat4 model;             // the mirror's mesh to world
  mat4 inv_reflection;    // inverse of the reflection pass's proj * view (depth -> world)
  vec4 plane;             // xyz unit normal toward the reflecting side, w offset
  vec4 eye;               // xyz world eye; w 1 = the camera sees the back (no reflection)
  vec4 extent;            // main view: 1/width, 1/height; reflection: focal_px, mip levels
  vec4 tint;              // rgb reflectance; w roughness
  vec4 base_color;        // rgb; w ior
  vec4 back_color;        // rgb; w fade distance (0: none)
  vec4 distortion;        // x uv offset per unit slope, y normal-map tiles
} mirror;

layout(set = 0, binding = 1) uniform sampler2D reflection;       // colour with mips
layout(set = 0, binding = 2) uniform sampler2D reflection_depth; // its depth (nearest)
layout(set = 0, binding = 3) uniform sampler2D normal_map;       // tangent-space normals

// Variants (specialization constants): lavapipe runs every branch, so a sharp metal mirror must
// not pay for blur, Fresnel, fade and the normal map.
layout(constant_id = 0) const bool kRough = false;      // roughness > 0
layout(constant_id = 1) const bool kDielectric = false; // fresnel = dielectric
layout(constant_id = 2) const bool kFade = false;       // fade_distance > 0
layout(constant_id = 3) const bool kNormalMap = false;  // a normal map distorts

#endif
