// Snell math: clipping the scene to one side of a plane (water reflection / refraction passes).
#pragma once

#include "conventions.hpp"
#include "plane.hpp"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace snell {

/// The world plane expressed in the clip space of `view_proj` (seed 001's method: the plane
/// vector times the inverse-transpose of view-projection).
///
/// For a world point `p` with clip position `c = view_proj * vec4(p, 1)`,
/// `dot(result, c) == signed_distance(world, p)`: the result is deliberately *not* renormalised,
/// so a vertex shader can write `gl_ClipDistance[0] = dot(result, gl_Position)` and clip in
/// world units. `view_proj` must be invertible (a singular matrix gives the zero vector, which
/// clips nothing).
[[nodiscard]] inline glm::vec4 clip_space_plane(const Plane& world,
                                                const glm::mat4& view_proj) noexcept {
  const float det = glm::determinant(view_proj);
  if (!std::isfinite(det) || std::fabs(det) < 1e-30f) {
    return glm::vec4(0.0f);
  }
  return glm::transpose(glm::inverse(view_proj)) * to_vec4(world);
}

/// Lengyel's oblique near-plane clipping ("Oblique View Frustum Depth Projection and Clipping",
/// Journal of Game Development 1(2), 2005), generalised to three depth ranges.
///
/// @param proj a perspective projection whose clip w is the view-space distance along the view
///        axis (any `perspective` of this library, with finite or infinite far plane, y flipped or
///        not).
/// @param view_space_plane the clip plane `(n, d)` in *view* space, positive on the side to
///        keep (e.g. `to_vec4(transform_plane(world, view))`). Need not be normalised.
/// @param range the depth range `proj` was built for.
/// @return `proj` with its depth row replaced so that the near plane is the clip plane: a point
///        on the plane gets NDC depth `near_depth(range)`, points on the kept side inside the
///        original frustum keep depths between near and far, points on the other side are
///        clipped. The far plane becomes oblique through the frustum corner farthest from the
///        plane (taken from the signs of the *clip-space* plane, so a flipped-y projection is
///        handled), which keeps every kept point of the original frustum; depth precision is
///        redistributed, so do not reuse this depth buffer with the unmodified projection.
///
/// When the whole original frustum lies on the clipped side (a camera looking away from the
/// plane), every point gets a depth beyond the near plane, so everything is clipped.
///
/// Precondition: the eye (view-space origin) is strictly on the clipped side
/// (`view_space_plane.w < 0`), as for a mirrored camera below a water surface or a camera above
/// the water looking into it. When it is not (eye on the plane or on the kept side), no oblique
/// near plane can keep the frustum and `proj` is returned unchanged: clip with
/// `gl_ClipDistance` instead (the water effect does this automatically).
[[nodiscard]] inline glm::mat4 oblique_projection(const glm::mat4& proj, glm::vec4 view_space_plane,
                                                  DepthRange range) noexcept {
  const glm::vec4& c = view_space_plane;
  if (!(c.w < 0.0f) || !std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) ||
      !std::isfinite(c.w)) {
    return proj;
  }
  const glm::mat4 inv = glm::inverse(proj);
  // The plane in clip space gives the corner signs; a view-space shortcut would assume
  // proj[0][0] > 0 and proj[1][1] > 0, which a Vulkan y-flipped projection violates.
  const glm::vec4 clip_plane = glm::transpose(inv) * c;
  const glm::vec4 corner_clip(clip_plane.x >= 0.0f ? 1.0f : -1.0f,
                              clip_plane.y >= 0.0f ? 1.0f : -1.0f, far_depth(range), 1.0f);
  // Homogeneous on purpose: with an infinite far plane the corner is a point at infinity (w=0).
  const glm::vec4 q = inv * corner_clip;
  const glm::vec4 row_w(proj[0][3], proj[1][3], proj[2][3], proj[3][3]);
  const float c_dot_q = glm::dot(c, q);
  const float w_dot_q = glm::dot(row_w, q);
  if (!std::isfinite(c_dot_q) || !std::isfinite(w_dot_q)) {
    return proj;
  }
  glm::vec4 row_z;
  if (!(c_dot_q > 0.0f)) {
    // q maximises the plane distance over the frustum (for an eye on the clipped side the
    // distance grows with depth), so the whole frustum is on the clipped side: clip everything
    // by putting every depth beyond the near plane.
    const float beyond = range == DepthRange::one_to_zero ? 2.0f : near_depth(range) - 1.0f;
    row_z = row_w * beyond;
    glm::mat4 m = proj;
    for (int col = 0; col < 4; ++col) {
      m[col][2] = row_z[col];
    }
    return m;
  }
  switch (range) {
  case DepthRange::minus_one_to_one: // near: z + w >= 0, far: w - z >= 0 through q
    row_z = c * (2.0f * w_dot_q / c_dot_q) - row_w;
    break;
  case DepthRange::zero_to_one: // near: z >= 0, far: w - z >= 0 through q
    row_z = c * (w_dot_q / c_dot_q);
    break;
  case DepthRange::one_to_zero: // near: w - z >= 0, far: z >= 0 through q
    row_z = row_w - c * (w_dot_q / c_dot_q);
    break;
  }
  glm::mat4 m = proj;
  for (int col = 0; col < 4; ++col) {
    m[col][2] = row_z[col];
  }
  return m;
}

} // namespace snell
