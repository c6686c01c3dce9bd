// Snell math: refraction (Snell's law) and Fresnel reflectance for dielectrics.
//
// Conventions: `eta = n1 / n2`, incident medium over transmitted medium, as GLSL `refract`.
// Directions are unit vectors; the incident direction points *toward* the surface and the
// normal points back into the incident medium (`dot(incident, normal) <= 0`).
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace snell {

/// Indices of refraction of common media (sodium D line, ~589 nm).
namespace ior {
inline constexpr float vacuum = 1.0f;
inline constexpr float air = 1.000293f;
inline constexpr float water = 1.333f;
inline constexpr float ice = 1.31f;
inline constexpr float glass = 1.5f;
inline constexpr float diamond = 2.417f;
} // namespace ior

/// Vector form of Snell's law, `n1 sin(theta1) = n2 sin(theta2)`, as GLSL `refract`.
///
/// @param incident unit direction of travel, toward the surface.
/// @param normal unit surface normal facing the incident side (`dot(incident, normal) <= 0`; to
///        refract out of a surface pass the flipped normal).
/// @param eta n1 / n2 (> 0).
/// @return the unit transmitted direction (in the plane of `incident` and `normal`), or
///         `std::nullopt` under total internal reflection (`eta * sin(theta1) > 1`, only
///         possible when leaving a denser medium, eta > 1). At exactly the critical angle the
///         result is tangent to the surface. At grazing incidence (theta1 = 90 degrees) the ray
///         is refracted at the critical angle when eta < 1.
[[nodiscard]] inline std::optional<glm::vec3> refract(glm::vec3 incident, glm::vec3 normal,
                                                      float eta) noexcept {
  const float cos_i = glm::dot(normal, incident);
  const float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
  if (k < 0.0f) {
    return std::nullopt;
  }
  return eta * incident - (eta * cos_i + std::sqrt(k)) * normal;
}

/// Exact unpolarised Fresnel reflectance of a smooth dielectric interface: the mean of the s-
/// and p-polarised reflectances from the Fresnel equations.
///
/// @param cos_theta_i cosine of the angle between the incident ray and the normal; its absolute
///        value is used and clamped to [0, 1], so `dot(-incident, normal)` with either normal
///        orientation works.
/// @param eta n1 / n2 (> 0). eta > 1 means the ray leaves the denser medium: beyond the critical
///        angle the result is exactly 1 (total internal reflection).
/// @return reflectance in [0, 1]; the transmitted fraction is 1 minus it. Air to glass (eta =
///         1/1.5): 0.04 at normal incidence, 1 at grazing incidence. Identical media (eta == 1)
///         reflect nothing.
[[nodiscard]] inline float fresnel_dielectric(float cos_theta_i, float eta) noexcept {
  const float cos_i = std::min(std::fabs(cos_theta_i), 1.0f);
  if (eta == 1.0f) {
    return 0.0f;
  }
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  if (sin2_t >= 1.0f) {
    return 1.0f; // total internal reflection (or grazing at exactly the critical angle)
  }
  const float cos_t = std::sqrt(1.0f - sin2_t); // > 0 here, so no division by zero below
  const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

/// Schlick's approximation `f0 + (1 - f0) (1 - cos)^5` of the Fresnel reflectance.
///
/// @param cos_theta_i cosine of the incidence angle, in [0, 1] (clamped; absolute value used).
///        When the ray leaves the denser medium pass the cosine of the *transmitted* angle
///        instead (and use 1 under total internal reflection), or use `fresnel_dielectric`.
/// @param f0 reflectance at normal incidence, in [0, 1] (see `f0_from_ior`).
[[nodiscard]] inline float fresnel_schlick(float cos_theta_i, float f0) noexcept {
  const float c = std::min(std::fabs(cos_theta_i), 1.0f);
  const float m = 1.0f - c;
  const float m2 = m * m;
  return f0 + (1.0f - f0) * (m2 * m2 * m);
}

/// Reflectance at normal incidence, `((n1 - n2) / (n1 + n2))^2`; symmetric in the two media.
/// Air/glass: 0.04; air/water: ~0.02. Indices must be > 0.
[[nodiscard]] inline float f0_from_ior(float n1, float n2) noexcept {
  const float r = (n1 - n2) / (n1 + n2);
  return r * r;
}

/// Critical angle for total internal reflection, in radians, `asin(n2 / n1)`, for a ray going
/// from medium n1 into medium n2. Never NaN: when `n1 <= n2` there is no total internal
/// reflection and the result is pi/2. Water to air: 48.6 degrees; glass (1.5) to air: 41.81.
[[nodiscard]] inline float critical_angle(float n1, float n2) noexcept {
  if (!(n1 > n2)) {
    return glm::half_pi<float>();
  }
  return std::asin(n2 / n1);
}

/// Sideways displacement of a ray that crosses a slab with parallel faces (a window pane, a
/// glass block): it enters at angle theta_i, travels at theta_t inside (Snell) and leaves
/// parallel to where it came from, shifted perpendicular to its direction by
/// `thickness * sin(theta_i - theta_t) / cos(theta_t)`.
///
/// @param thickness distance between the faces (any unit; the result is in the same), >= 0.
/// @param cos_theta_i cosine of the incidence angle at the entry face, in [0, 1] (clamped;
///        absolute value used).
/// @param eta n1 / n2, outside over inside (> 0); a slab of glass in air: 1 / 1.5.
/// @return the shift, >= 0 (0 at normal incidence and for eta == 1; it grows with the angle
///         and reaches `thickness` at grazing incidence from the rarer medium), or
///         `std::nullopt` when the ray cannot enter (total internal reflection, eta > 1 beyond
///         the critical angle).
[[nodiscard]] inline std::optional<float> slab_lateral_shift(float thickness, float cos_theta_i,
                                                             float eta) noexcept {
  const float cos_i = std::min(std::abs(cos_theta_i), 1.0f);
  const float sin_i = std::sqrt(std::max(0.0f, 1.0f - cos_i * cos_i));
  const float sin_t = eta * sin_i;
  if (sin_t > 1.0f) {
    return std::nullopt;
  }
  const float cos_t = std::sqrt(std::max(0.0f, 1.0f - sin_t * sin_t));
  if (cos_t <= 0.0f) {
    return std::nullopt; // exactly at the critical angle: the ray runs along the face
  }
  // sin(ti - tt) = sin_i cos_t - cos_i sin_t
  return thickness * (sin_i * cos_t - cos_i * sin_t) / cos_t;
}

/// Per-channel indices of refraction for dispersion, as KHR_materials_dispersion defines it:
/// `dispersion` = 20 / V_d, V_d the Abbe number (n_d - 1) / (n_F - n_C), so the spread between
/// the blue F line (486 nm) and the red C line (656 nm) is n_F - n_C = (ior - 1) dispersion / 20;
/// red gets ior minus half of it, green ior, blue ior plus half.
///
/// @param ior index of refraction at the d line (587.6 nm), >= 1.
/// @param dispersion 20 / V_d, >= 0 (0: none; crown glass BK7 ~0.31, flint glass SF11 ~0.78).
/// @return (n_red, n_green, n_blue).
[[nodiscard]] inline glm::vec3 dispersion_iors(float ior, float dispersion) noexcept {
  const float half_spread = (ior - 1.0f) * dispersion * 0.025f;
  return {ior - half_spread, ior, ior + half_spread};
}

} // namespace snell
