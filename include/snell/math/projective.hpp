// Snell math: projective texture coordinates (sampling a render target rendered from a camera
// at the screen position of a surface point, seeds 000, 001, 003).
#pragma once

#include "conventions.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace snell {

/// The bias matrix `B` that maps a clip position `c` to `(u*w, v*w, depth01*w, w)`, so that
/// after the divide by `w` (or with `textureProj`) `u, v` address the texture rendered with that
/// clip space and `depth01` is the depth-buffer value in [0,1]:
/// - `vulkan`: u = 0.5 x/w + 0.5, v = 0.5 y/w + 0.5, depth01 = z/w;
/// - `opengl`: u = 0.5 x/w + 0.5, v = 0.5 y/w + 0.5, depth01 = 0.5 z/w + 0.5;
/// - `d3d`:    u = 0.5 x/w + 0.5, v = -0.5 y/w + 0.5, depth01 = z/w (the seeds' formula).
/// Use `clip_to_uv(conv) * proj * view` as a texture matrix.
[[nodiscard]] inline glm::mat4 clip_to_uv(ClipConvention convention) noexcept {
  glm::mat4 b(0.0f);
  b[0][0] = 0.5f;
  b[3][0] = 0.5f;
  b[1][1] = convention == ClipConvention::d3d ? -0.5f : 0.5f;
  b[3][1] = 0.5f;
  if (convention == ClipConvention::opengl) {
    b[2][2] = 0.5f;
    b[3][2] = 0.5f;
  } else {
    b[2][2] = 1.0f;
  }
  b[3][3] = 1.0f;
  return b;
}

/// The texture coordinate of a clip position: divide by `w`, then apply `clip_to_uv`.
/// Points inside the view frustum land in [0,1]^2. `clip.w` must be non-zero; points behind the
/// eye (w < 0) give the point-reflected coordinate, as the GPU's divide would, and are not
/// meaningful; at w == 0 the result is non-finite.
[[nodiscard]] inline glm::vec2 project_to_uv(glm::vec4 clip, ClipConvention convention) noexcept {
  const float x = clip.x / clip.w;
  const float y = clip.y / clip.w;
  const float v = convention == ClipConvention::d3d ? -0.5f * y + 0.5f : 0.5f * y + 0.5f;
  return glm::vec2(0.5f * x + 0.5f, v);
}

} // namespace snell
