// Snell math: planes `n . p + d = 0`.
#pragma once

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace snell {

/// A plane `dot(normal, p) + d = 0`.
///
/// Conventions: `normal` is unit length for a normalised plane (every function that builds a
/// plane returns one normalised); the positive side is the half-space `normal` points into.
/// The horizontal water plane `y = h` with its positive side up is `Plane{{0, 1, 0}, -h}`.
/// A plane whose normal is the zero vector is *degenerate* (see `is_degenerate`); functions
/// document what they do with one and never divide by zero.
struct Plane {
  glm::vec3 normal{0.0f, 1.0f, 0.0f}; ///< Unit normal; default +Y (the plane y = 0).
  float d = 0.0f;                     ///< Offset: signed distance of the origin. Default 0.
};

/// True when the plane has no usable normal: |normal|^2 <= 1e-20 (|normal| <= 1e-10), or the
/// normal or `d` is not finite.
[[nodiscard]] inline bool is_degenerate(const Plane& plane) noexcept {
  const float len2 = glm::dot(plane.normal, plane.normal);
  return !(len2 > 1e-20f) || !std::isfinite(len2) || !std::isfinite(plane.d);
}

/// The plane with unit normal and offset scaled alike, describing the same point set.
/// A degenerate plane is returned unchanged.
[[nodiscard]] inline Plane normalize(const Plane& plane) noexcept {
  if (is_degenerate(plane)) {
    return plane;
  }
  const float inv_len = 1.0f / glm::length(plane.normal);
  return Plane{plane.normal * inv_len, plane.d * inv_len};
}

/// The plane through `point` with positive side toward `normal` (normalised here; any
/// non-zero length). A zero normal gives the degenerate plane `{{0,0,0}, 0}`.
[[nodiscard]] inline Plane plane_from_point_normal(glm::vec3 point, glm::vec3 normal) noexcept {
  const Plane raw{normal, 0.0f};
  if (is_degenerate(raw)) {
    return Plane{glm::vec3(0.0f), 0.0f};
  }
  const glm::vec3 n = glm::normalize(normal);
  return Plane{n, -glm::dot(n, point)};
}

/// Signed distance of `p` to the plane, in world units when the plane is normalised:
/// positive on the side the normal points to, zero on the plane. (For an unnormalised plane it
/// is the distance times |normal|; for a zero normal it is `d`, for a non-finite one NaN.)
[[nodiscard]] inline float signed_distance(const Plane& plane, glm::vec3 p) noexcept {
  return glm::dot(plane.normal, p) + plane.d;
}

/// The plane as `(normal.x, normal.y, normal.z, d)`, the form shaders take: for a point `p`,
/// `dot(to_vec4(plane), vec4(p, 1))` is the signed distance.
[[nodiscard]] inline glm::vec4 to_vec4(const Plane& plane) noexcept {
  return glm::vec4(plane.normal, plane.d);
}

/// The plane from a `(n, d)` vector (not normalised here; see `normalize`).
[[nodiscard]] inline Plane plane_from_vec4(glm::vec4 v) noexcept {
  return Plane{glm::vec3(v), v.w};
}

/// The plane transformed by the point transform `m`: if `p` lies on `plane`, `m * p` lies on the
/// result. Planes are covectors, so they transform by the inverse-transpose `(m^-1)^T`; the
/// result is normalised and keeps the side orientation (a point on the positive side maps to the
/// positive side). `m` must be invertible; a singular or non-finite `m`, or a degenerate plane,
/// gives the degenerate plane `{{0,0,0}, 0}`.
[[nodiscard]] inline Plane transform_plane(const Plane& plane, const glm::mat4& m) noexcept {
  const float det = glm::determinant(m);
  if (is_degenerate(plane) || !std::isfinite(det) || std::fabs(det) < 1e-30f) {
    return Plane{glm::vec3(0.0f), 0.0f};
  }
  const glm::vec4 v = glm::transpose(glm::inverse(m)) * to_vec4(plane);
  const Plane out = normalize(plane_from_vec4(v));
  return is_degenerate(out) ? Plane{glm::vec3(0.0f), 0.0f} : out;
}

} // namespace snell
