// Snell math: axis-aligned boxes and conservative visibility tests (culling).
#pragma once

#include "conventions.hpp"
#include "plane.hpp"

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace snell {

/// An axis-aligned box `[min, max]` per axis. A box with `min > max` on any axis is *empty*
/// (`Aabb{}` is empty: it contains nothing and every test below treats it as invisible).
struct Aabb {
  /// Smallest corner. Default +infinity (empty box).
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  /// Largest corner. Default -infinity (empty box).
  glm::vec3 max{-std::numeric_limits<float>::infinity()};
};

/// True when the box contains no point (min > max on some axis, or a NaN bound).
[[nodiscard]] inline bool is_empty(const Aabb& box) noexcept {
  return !(box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z);
}

/// The box grown to contain `p`.
[[nodiscard]] inline Aabb expand(const Aabb& box, glm::vec3 p) noexcept {
  return Aabb{glm::min(box.min, p), glm::max(box.max, p)};
}

/// Corner `i` (0..7) of the box: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
[[nodiscard]] inline glm::vec3 corner(const Aabb& box, int i) noexcept {
  return glm::vec3((i & 1) != 0 ? box.max.x : box.min.x, (i & 2) != 0 ? box.max.y : box.min.y,
                   (i & 4) != 0 ? box.max.z : box.min.z);
}

/// The axis-aligned box around `box` transformed by the affine matrix `m` (Arvo's method: exact
/// bounds of the eight transformed corners). An empty box stays empty. The projective row of `m`
/// is ignored: pass model (world) matrices, not projections.
[[nodiscard]] inline Aabb transform_aabb(const Aabb& box, const glm::mat4& m) noexcept {
  if (is_empty(box)) {
    return box;
  }
  glm::vec3 lo(m[3]);
  glm::vec3 hi(m[3]);
  for (int col = 0; col < 3; ++col) {
    const glm::vec3 a = glm::vec3(m[col]) * box.min[col];
    const glm::vec3 b = glm::vec3(m[col]) * box.max[col];
    lo += glm::min(a, b);
    hi += glm::max(a, b);
  }
  return Aabb{lo, hi};
}

/// True when the whole box lies strictly on the negative side of `plane` (n . p + d < 0 for
/// every point), i.e. a clip plane that keeps the positive side removes all of it. The plane
/// need not be normalised. An empty box is below every plane; a degenerate plane has nothing
/// below it (returns false for a non-empty box).
[[nodiscard]] inline bool aabb_below_plane(const Aabb& box, const Plane& plane) noexcept {
  if (is_empty(box)) {
    return true;
  }
  if (is_degenerate(plane)) {
    return false;
  }
  // The corner furthest along the normal (the support point) decides.
  const glm::vec3 support(plane.normal.x >= 0.0f ? box.max.x : box.min.x,
                          plane.normal.y >= 0.0f ? box.max.y : box.min.y,
                          plane.normal.z >= 0.0f ? box.max.z : box.min.z);
  return glm::dot(plane.normal, support) + plane.d < 0.0f;
}

/// Conservative clip-space rejection: true when all eight corners of `box`, transformed by
/// `clip_from_box` (projection * view * model), lie outside one and the same boundary of the
/// clip volume restricted to `ndc_rect` = (x0, y0, x1, y1) in normalised device coordinates
/// (pass (-1, -1, 1, 1) for the whole viewport; a scissor rectangle in pixels maps to
/// x = 2 px / width - 1, y = 2 py / height - 1 with Vulkan's standard viewport). The depth
/// boundaries are those of `depth` (zero_to_one and one_to_zero keep 0 <= z <= w,
/// minus_one_to_one keeps -w <= z <= w). Tests in homogeneous coordinates, so corners behind
/// the eye (w <= 0) are handled without a divide. False does not prove visibility (a box may
/// straddle a frustum corner); true proves the box draws nothing. An empty box returns true.
[[nodiscard]] inline bool aabb_outside_clip(const Aabb& box, const glm::mat4& clip_from_box,
                                            glm::vec4 ndc_rect, DepthRange depth) noexcept {
  if (is_empty(box)) {
    return true;
  }
  // One bit per boundary: set while every corner seen so far is outside it.
  unsigned outside_all = 0x3Fu;
  const float z_min_scale = depth == DepthRange::minus_one_to_one ? -1.0f : 0.0f;
  for (int i = 0; i < 8 && outside_all != 0u; ++i) {
    const glm::vec4 c = clip_from_box * glm::vec4(corner(box, i), 1.0f);
    unsigned out = 0u;
    out |= c.x < ndc_rect.x * c.w ? 0x01u : 0u;
    out |= c.x > ndc_rect.z * c.w ? 0x02u : 0u;
    out |= c.y < ndc_rect.y * c.w ? 0x04u : 0u;
    out |= c.y > ndc_rect.w * c.w ? 0x08u : 0u;
    out |= c.z < z_min_scale * c.w ? 0x10u : 0u;
    out |= c.z > c.w ? 0x20u : 0u;
    outside_all &= out;
  }
  return outside_all != 0u;
}

} // namespace snell
