// Snell math: mirroring across a plane (planar reflections, seeds 000 and 001).
#pragma once

#include "plane.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace snell {

/// The affine mirror across `plane`: `p' = p - 2 (n.p + d) n` for unit `n`.
///
/// Properties: determinant -1 (it flips handedness, so triangle winding flips in mirrored
/// views), an involution (`R * R == I`), points on the plane are fixed. The plane is normalised
/// first, so any non-zero normal length works. A degenerate plane gives the identity.
[[nodiscard]] inline glm::mat4 reflection_matrix(const Plane& plane) noexcept {
  if (is_degenerate(plane)) {
    return glm::mat4(1.0f);
  }
  const Plane p = normalize(plane);
  const glm::vec3 n = p.normal;
  glm::mat4 r(1.0f);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      r[col][row] -= 2.0f * n[row] * n[col];
    }
  }
  r[3] = glm::vec4(-2.0f * p.d * n, 1.0f);
  return r;
}

/// The view matrix of the mirrored camera: `view * reflection_matrix(plane)`. It maps a world
/// point to where the original camera sees its mirror image. Its determinant is -1, so
/// pipelines that draw with it must swap their front face (see docs/conventions.md). The
/// mirrored eye is `reflect_point(plane, eye)`.
[[nodiscard]] inline glm::mat4 reflect_view(const glm::mat4& view, const Plane& plane) noexcept {
  return view * reflection_matrix(plane);
}

/// The mirror image of the point `p` across `plane` (identity for a degenerate plane).
[[nodiscard]] inline glm::vec3 reflect_point(const Plane& plane, glm::vec3 p) noexcept {
  if (is_degenerate(plane)) {
    return p;
  }
  const Plane n = normalize(plane);
  return p - 2.0f * signed_distance(n, p) * n.normal;
}

/// The mirror image of the direction `v` across `plane` (translation ignored): the GLSL
/// `reflect(v, n)` with the plane's unit normal. Identity for a degenerate plane.
[[nodiscard]] inline glm::vec3 reflect_direction(const Plane& plane, glm::vec3 v) noexcept {
  if (is_degenerate(plane)) {
    return v;
  }
  const glm::vec3 n = normalize(plane).normal;
  return v - 2.0f * glm::dot(n, v) * n;
}

} // namespace snell
