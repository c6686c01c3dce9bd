// Snell math: view and projection matrices with explicit conventions.
//
// GLM's own `glm::perspective` and `glm::lookAt` change behaviour with GLM_FORCE_DEPTH_ZERO_TO_ONE
// and GLM_FORCE_LEFT_HANDED; these do not: the depth range is an argument and the handedness
// is always right-handed (camera looks down -Z in view space, +Y up).
#pragma once

#include "conventions.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <limits>

namespace snell {

/// Right-handed perspective projection (view space looks down -Z, clip y up).
///
/// @param fovy_radians vertical field of view in radians, in (0, pi).
/// @param aspect width / height, > 0.
/// @param z_near distance to the near plane, > 0.
/// @param z_far distance to the far plane, > z_near; `+infinity` gives an infinite far plane
///        (the limit of the finite matrix, so depth approaches far_depth(range) at infinity).
/// @param range which NDC depths the near and far planes map to.
/// Clip y points up (OpenGL style). For Vulkan with a standard viewport, apply `flip_clip_y`
/// (what Snell's runtime does, see docs/conventions.md). Violated preconditions give a
/// non-finite or meaningless matrix; callers validate user input first.
[[nodiscard]] inline glm::mat4 perspective(float fovy_radians, float aspect, float z_near,
                                           float z_far, DepthRange range) noexcept {
  const float f = 1.0f / std::tan(0.5f * fovy_radians);
  const bool infinite = std::isinf(z_far);
  glm::mat4 m(0.0f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][3] = -1.0f;
  switch (range) {
  case DepthRange::minus_one_to_one:
    m[2][2] = infinite ? -1.0f : -(z_far + z_near) / (z_far - z_near);
    m[3][2] = infinite ? -2.0f * z_near : -2.0f * z_far * z_near / (z_far - z_near);
    break;
  case DepthRange::zero_to_one:
    m[2][2] = infinite ? -1.0f : -z_far / (z_far - z_near);
    m[3][2] = infinite ? -z_near : -z_far * z_near / (z_far - z_near);
    break;
  case DepthRange::one_to_zero:
    m[2][2] = infinite ? 0.0f : z_near / (z_far - z_near);
    m[3][2] = infinite ? z_near : z_far * z_near / (z_far - z_near);
    break;
  }
  return m;
}

/// `proj` with clip-space y negated (its second row negated), turning a y-up projection into a
/// Vulkan y-down one for a standard, positive-height viewport. Works for any matrix, including
/// oblique ones; applying it twice gives `proj` back. Flipping y mirrors the image, so it flips
/// the winding seen by the rasteriser too.
[[nodiscard]] inline glm::mat4 flip_clip_y(const glm::mat4& proj) noexcept {
  glm::mat4 m = proj;
  for (int col = 0; col < 4; ++col) {
    m[col][1] = -m[col][1];
  }
  return m;
}

/// Right-handed look-at view matrix: the eye at `eye` looks at `target`, `up` is roughly up.
/// When `up` is (nearly) parallel to the view direction another up axis is chosen (+Z, or +X
/// if that is parallel too); when `eye == target` the view looks down -Z from `eye`.
[[nodiscard]] inline glm::mat4 look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up) noexcept {
  glm::vec3 forward = target - eye;
  const float flen = glm::length(forward);
  forward = flen > 1e-20f ? forward / flen : glm::vec3(0.0f, 0.0f, -1.0f);
  glm::vec3 right = glm::cross(forward, up);
  if (!(glm::length(right) > 1e-6f * glm::length(up))) {
    right = glm::cross(forward, glm::vec3(0.0f, 0.0f, 1.0f));
    if (!(glm::length(right) > 1e-6f)) {
      right = glm::cross(forward, glm::vec3(1.0f, 0.0f, 0.0f));
    }
  }
  right = glm::normalize(right);
  const glm::vec3 true_up = glm::cross(right, forward);
  glm::mat4 v(1.0f);
  for (int i = 0; i < 3; ++i) {
    v[i][0] = right[i];
    v[i][1] = true_up[i];
    v[i][2] = -forward[i];
  }
  v[3][0] = -glm::dot(right, eye);
  v[3][1] = -glm::dot(true_up, eye);
  v[3][2] = glm::dot(forward, eye);
  return v;
}

} // namespace snell
