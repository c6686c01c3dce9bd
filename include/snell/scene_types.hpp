// Snell: the small scene vocabulary that host-facing headers need (layer bits, the light)
// without the scene model (meshes, materials, images, the glTF loader) of snell/scene.hpp.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>

namespace snell {

/// Which passes an object takes part in (bit mask). The seeds' IsReflected / IsRefracted.
namespace layer {
inline constexpr std::uint32_t main = 1u << 0;      ///< Drawn in the main view.
inline constexpr std::uint32_t reflected = 1u << 1; ///< Drawn in planar reflections.
inline constexpr std::uint32_t refracted = 1u << 2; ///< Drawn in refraction passes.
inline constexpr std::uint32_t captured = 1u << 3;  ///< Drawn into dynamic cube maps.
inline constexpr std::uint32_t all = main | reflected | refracted | captured;
} // namespace layer

/// One directional light (glTF KHR_lights_punctual "directional").
struct DirectionalLight {
  glm::vec3 direction{-0.4f, -1.0f, -0.3f}; ///< Direction the light travels (toward the scene).
  glm::vec3 color{1.0f, 0.97f, 0.9f};       ///< Linear colour. Default warm white.
  float intensity = 1.0f;                   ///< Multiplier. Default 1.
  glm::vec3 ambient{0.25f, 0.28f, 0.32f};   ///< Ambient term added to every surface.
};

} // namespace snell
