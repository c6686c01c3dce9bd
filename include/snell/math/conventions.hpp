// Snell math: clip-space conventions passed explicitly as arguments.
//
// Nothing in snell/math reads GLM_FORCE_* configuration macros: every function whose result
// depends on a depth range or on a clip-space/texture convention takes it as an argument.
#pragma once

#include <cstdint>

namespace snell {

/// Which normalised-device depth values the near and far planes map to.
enum class DepthRange : std::uint8_t {
  zero_to_one,      ///< Vulkan / D3D: near -> 0, far -> 1.
  minus_one_to_one, ///< OpenGL default: near -> -1, far -> +1.
  one_to_zero,      ///< Reversed Z (Vulkan / D3D with a float depth buffer): near -> 1, far -> 0.
};

/// Clip-space and texture-coordinate conventions of the three common APIs.
///
/// - `vulkan`: depth [0,1]; a standard (positive-height) viewport puts NDC y = -1 on the first
///   image row, and texture v = 0 is the first row, so v = 0.5 * y/w + 0.5. This is the
///   convention of Snell's runtime (see docs/conventions.md).
/// - `opengl`: depth [-1,1]; NDC y = -1 is window row 0 and texture t = 0 is the first row in
///   memory (the bottom of the picture), so t = 0.5 * y/w + 0.5 and depth' = 0.5 * z/w + 0.5.
/// - `d3d`: depth [0,1]; NDC y = +1 is the top row and v = 0 is the top row, so
///   v = -0.5 * y/w + 0.5 (the form the seed tutorials use).
enum class ClipConvention : std::uint8_t { vulkan, opengl, d3d };

/// NDC depth of the near plane for `range`: 0, -1 or 1.
[[nodiscard]] constexpr float near_depth(DepthRange range) noexcept {
  switch (range) {
  case DepthRange::zero_to_one:
    return 0.0f;
  case DepthRange::minus_one_to_one:
    return -1.0f;
  case DepthRange::one_to_zero:
    return 1.0f;
  }
  return 0.0f;
}

/// NDC depth of the far plane for `range`: 1, 1 or 0.
[[nodiscard]] constexpr float far_depth(DepthRange range) noexcept {
  return range == DepthRange::one_to_zero ? 0.0f : 1.0f;
}

/// The depth range an API's clip space uses (`opengl` -> minus_one_to_one, else zero_to_one).
[[nodiscard]] constexpr DepthRange depth_range_of(ClipConvention convention) noexcept {
  return convention == ClipConvention::opengl ? DepthRange::minus_one_to_one
                                              : DepthRange::zero_to_one;
}

} // namespace snell
