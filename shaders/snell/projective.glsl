// Snell math mirrors (GLSL): projective texture coordinates (include/snell/math/projective.hpp).
#ifndef SNELL_PROJECTIVE_GLSL
#define SNELL_PROJECTIVE_GLSL

const int SNELL_CLIP_VULKAN = 0; // ClipConvention::vulkan
const int SNELL_CLIP_OPENGL = 1; // ClipConvention::opengl
const int SNELL_CLIP_D3D = 2;    // ClipConvention::d3d

// Texture coordinate of a clip position: divide by w, then bias (v flipped for D3D).
vec2 project_to_uv(vec4 clip, int convention) {
  vec2 ndc = clip.xy / clip.w;
  float v = convention == SNELL_CLIP_D3D ? -0.5 * ndc.y + 0.5 : 0.5 * ndc.y + 0.5;
  return vec2(0.5 * ndc.x + 0.5, v);
}

#endif
