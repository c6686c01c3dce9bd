// Snell plugin "water": planar water with reflection and refraction render targets (seeds 000
// and 001), made correct for Vulkan and physically grounded. See docs/water.md.
#pragma once

#include <snell/effect.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace snell {

/// How the reflection and refraction passes are clipped at the water surface.
enum class WaterClipMode : std::uint8_t {
  oblique,       ///< Lengyel's oblique near plane (no extra per-vertex work). Default.
  clip_distance, ///< gl_ClipDistance against the plane (seed 001's clip plane).
};

/// Which Fresnel term blends reflection over refraction.
enum class WaterFresnel : std::uint8_t {
  exact,    ///< Exact unpolarised dielectric Fresnel with `ior` (default).
  schlick,  ///< Schlick's approximation with f0 from `ior`.
  seed,     ///< Seed 001's `1 - dot(eye, normal)` (not physical; for comparison).
  constant, ///< A fixed reflection weight `reflectance` (seed 000's lerp(..., 0.6)).
};

/// Where the refraction (what is seen through the surface) comes from.
enum class WaterRefractionSource : std::uint8_t {
  /// The frame's scene snapshot (FrameInfo::snapshot): no extra scene pass; every object the
  /// main view draws is refracted. Falls back to `pass` when the host gives no snapshot.
  /// Default.
  snapshot,
  /// A refraction pass of its own at resolution_scale, clipped at the surface, drawing
  /// refraction_layers (seeds 000/001).
  pass,
};

/// What the water surface shows.
enum class WaterDebugView : std::uint8_t { final, reflection, refraction, normals, fresnel };

/// The water's parameters. Every field documents its default and valid range; `snell list`
/// prints the same from the schema, and a test pins that the two agree.
struct WaterParams {
  /// Height of the water plane y = height, in world units (m). Default: the scene's "water"
  /// anchor, else 0. Range [-10000, 10000].
  float height = 0.0f;
  /// Centre (x, z) of the water rectangle, m. Default: the anchor's, else (0, 0). [-1e4, 1e4].
  glm::vec2 center{0.0f, 0.0f};
  /// Size (x, z) of the water rectangle, m. Default: the anchor's, else (10, 10). [0.01, 1e5].
  glm::vec2 size{10.0f, 10.0f};
  /// Reflection and refraction target size relative to the output. Default 0.5 (1.0 = seeds).
  /// [0.1, 1].
  float resolution_scale = 0.5f;
  /// Where the refraction comes from. Default snapshot (the pass when the host gives none).
  WaterRefractionSource refraction_source = WaterRefractionSource::snapshot;
  /// Clipping of the reflection/refraction passes. Default oblique.
  WaterClipMode clip_mode = WaterClipMode::oblique;
  /// How far past the surface each pass keeps geometry, m, so the water line shows no seam or
  /// gap: the reflection keeps y >= height - clip_offset, the refraction y <= height +
  /// clip_offset. Default 0.05 (seed 000 used 0.1). [0, 10].
  float clip_offset = 0.05f;
  /// World size of one tile of the ripple normal map, m. Default 4. [0.01, 1000].
  float wave_length = 4.0f;
  /// Ripple strength: scales the normal map's slopes. 0 = flat water. Default 0.3 (seed 001).
  /// [0, 4].
  float wave_height = 0.3f;
  /// Texture-space offset of the reflection/refraction lookups per unit of slope. Default
  /// 0.02 (seed 000's reflectRefractScale was 0.01). [0, 0.5].
  float distortion = 0.02f;
  /// Direction the ripples scroll (x, z); normalised internally; (0,0) means no wind. Default
  /// (0, 1) (seed 001's wind direction (0,0,1)). Components in [-1, 1].
  glm::vec2 wind_direction{0.0f, 1.0f};
  /// Scroll speed of the ripples, m/s. 0 = still water. Default 0.1. [0, 100].
  float wind_force = 0.1f;
  /// Fresnel term. Default exact.
  WaterFresnel fresnel = WaterFresnel::exact;
  /// Index of refraction of the water (the eye is in air, n = 1). Default 1.333. [1, 3].
  float ior = 1.333f;
  /// Reflection weight when fresnel == constant: colour = mix(refraction, reflection,
  /// reflectance). Default 0.4 (seed 000's lerp(reflection, refraction, 0.6)). [0, 1].
  float reflectance = 0.4f;
  /// Colour of the water body, linear RGB: what fully absorbed light becomes (in-scattering),
  /// and the seed's "dull colour". Default (0.02, 0.12, 0.14). Each [0, 1].
  glm::vec3 water_color{0.02f, 0.12f, 0.14f};
  /// Blend of the final colour toward water_color (seed 001: 0.2). Default 0. [0, 1].
  float color_blend = 0.0f;
  /// Exponent of the sun's specular highlight. Default 256 (seed 001). [1, 4096].
  float specular_power = 256.0f;
  /// Strength of the sun's specular highlight. Default 1. [0, 100].
  float specular_intensity = 1.0f;
  /// Beer-Lambert absorption per metre of water along the view ray, per channel (1/m).
  /// Default (0.45, 0.09, 0.07): red fades first. 0 = clear water. Each [0, 100].
  glm::vec3 absorption{0.45f, 0.09f, 0.07f};
  /// Soft shoreline: over the first shore_softness metres of water depth (read from the
  /// refraction pass's depth) the ripple distortion, the reflection and the highlight fade in,
  /// so the refracted ground meets the real ground without a seam. The surface stays opaque.
  /// 0 = hard edge. Default 0.15 m. [0, 100].
  float shore_softness = 0.15f;
  /// Objects seen on the water's upper side (snell::layer bits): drawn in the reflection seen
  /// from above, in the refraction seen from below. Default layer::reflected.
  int reflection_layers = static_cast<int>(layer::reflected);
  /// Objects seen on the water's lower side (snell::layer bits): drawn in the refraction seen
  /// from above, in the (totally internal) reflection seen from below. Default
  /// layer::refracted.
  int refraction_layers = static_cast<int>(layer::refracted);
  /// What the surface shows. Default final.
  WaterDebugView debug_view = WaterDebugView::final;
  /// Ripple normal map: a PNG/JPEG file (tangent-space, linear, green toward the image top,
  /// tileable), or "" for the built-in procedural one (256x256, seeded). Loaded when set; a
  /// missing or undecodable file is an error naming it. Default "".
  std::string normal_map{};
};

/// The `seed` preset: seeds 000/001 for side-by-side comparison: full-resolution targets,
/// seed 000's constant blend lerp(reflection, refraction, 0.6) (fresnel = constant,
/// reflectance 0.4), seed 001's dull colour (0.3, 0.3, 0.5) blended 0.2 and pow-256 specular,
/// distortion 0.01, clip offset 0.1, no absorption and no soft shoreline.
[[nodiscard]] WaterParams water_seed_preset(const WaterParams& base = {});

/// The water effect. Create it through the registry (`create("water", info)`) or directly with
/// create_water; cast to WaterEffect for the typed API. Per-frame uniforms and descriptors are
/// sized by EffectCreateInfo::frames_in_flight. A camera exactly
/// on the plane cannot use an oblique near plane; the passes then clip with gl_ClipDistance
/// whatever clip_mode says. From below the plane the passes swap sides: the surface shows
/// total internal reflection of the underwater scene and, inside Snell's window, the world
/// above (docs/water.md, "From under the water").
class WaterEffect : public Effect {
public:
  /// The typed parameters (validated as a whole; nothing is changed on error).
  [[nodiscard]] virtual Result<void> set_params(const WaterParams& params) = 0;
  [[nodiscard]] virtual const WaterParams& params() const = 0;
};

/// The water effect's schema (names, types, defaults from WaterParams{}, ranges, units, docs).
[[nodiscard]] const ParamSchema& water_schema();
/// Creates the water effect with default parameters; the "water" anchor of `info.scene`, if
/// any, sets height, center and size.
[[nodiscard]] Result<std::unique_ptr<WaterEffect>> create_water(const EffectCreateInfo& info);
/// Registers "water" in `registry`.
[[nodiscard]] Result<void> register_water(EffectRegistry& registry);

} // namespace snell
