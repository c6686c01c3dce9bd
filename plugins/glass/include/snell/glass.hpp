// Snell plugin "glass" and "ice": transmissive surfaces that show what is behind them (seed 003),
// made physically grounded. One implementation under two registered names with their own
// defaults. See docs/glass.md.
//
// What is drawn: a pane (a solid slab of `thickness` centred on `center`, facing `normal`, from
// the scene's "window" anchor when present) and every object of EffectCreateInfo::scene whose
// material has KHR_materials_transmission > 0 (their optics come from their material:
// ior, volume thickness and attenuation, dispersion, roughness, base colour as tint). What is
// behind comes from the frame's scene snapshot (FrameInfo::snapshot; a pass of the effect's own
// when the host gives none), displaced by the normal map x refraction_scale (the seed's way) and
// by the lateral shift of a solid slab; exact dielectric Fresnel reflects the sky.
#pragma once

#include <snell/effect.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace snell {

/// How the surfaces weigh reflection against transmission.
enum class GlassFresnel : std::uint8_t {
  exact, ///< Exact unpolarised dielectric Fresnel with the surface's IOR. Default.
  none,  ///< No reflection: transmission only (seed 003).
};

/// What the surfaces show (for debugging and tests).
enum class GlassDebugView : std::uint8_t {
  final,        ///< The shaded glass. Default.
  transmission, ///< The transmitted light alone (tinted, attenuated; not weighted by 1 - F).
  reflection,   ///< The reflected environment alone (not weighted by F).
  fresnel,      ///< The Fresnel reflectance F as grey.
  offset,       ///< The screen-space offset of the background lookup (x red, y green; 0.5 = 0).
};

/// Parameters of the glass and ice effects. The pane's optics are these fields; objects taken
/// from the scene use their material's instead (fresnel, debug_view, max_layers and the
/// specular apply to all). `snell list` prints the same from the schema; a test pins that
/// defaults agree. Ice's defaults are ice_defaults().
struct GlassParams {
  /// Draw the pane. Default true (an effect created with a scene that has transmissive objects
  /// but no "window" anchor starts with false).
  bool pane = true;
  /// Centre of the pane, world units (m). Default: the "window" anchor's, else (0, 1.5, 0).
  /// Each component in [-1e4, 1e4].
  glm::vec3 center{0.0f, 1.5f, 0.0f};
  /// Width and height of the pane, m. Default: the anchor's, else (2, 2). [0.01, 1e4].
  glm::vec2 size{2.0f, 2.0f};
  /// The side the pane faces (normalised internally). (0, 0, 0) turns the pane toward the eye
  /// every frame (a billboard). Its width runs along the horizontal of the plane, its height
  /// along world up projected into it (world -Z for a pane facing straight up or down).
  /// Default (0, 0, 1). Components in [-1, 1].
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  /// Thickness of the pane, m: a solid slab centred on `center`; light leaves it parallel to
  /// where it came from, shifted sideways by thickness * sin(ti - tt) / cos(tt). 0 =
  /// thin-walled (no shift), as glTF treats a transmissive material without a volume. Default 0
  /// (a 1 cm window shifts the view by under a pixel at a few metres, and the thin path is
  /// the cheapest). [0, 100].
  float thickness = 0.0f;
  /// Index of refraction (the eye is in air, n = 1). Default 1.5 (glass). [1, 3].
  float ior = 1.5f;
  /// KHR_materials_dispersion's 20 / Abbe number: per-channel IOR (red lower, blue higher,
  /// half-spread (ior - 1) * 0.025 * dispersion). 0 = none. Default 0. [0, 20].
  float dispersion = 0.0f;
  /// Surface roughness: frosted transmission from the snapshot's blurred levels. 0 = clear.
  /// Default 0. [0, 1].
  float roughness = 0.0f;
  /// Colour multiplying transmitted light (KHR_materials_transmission's base colour), linear
  /// RGB. Default (1, 1, 1). Each in [0, 1].
  glm::vec3 tint{1.0f, 1.0f, 1.0f};
  /// Beer-Lambert: the colour white light has after attenuation_distance inside the slab,
  /// linear RGB. Default (1, 1, 1) (no attenuation). Each in [0, 1].
  glm::vec3 attenuation_color{1.0f, 1.0f, 1.0f};
  /// Distance at which light inside is tinted to attenuation_color, m. Default 1.
  /// [0.001, 1e6].
  float attenuation_distance = 1.0f;
  /// Screen-space (uv) offset of the background lookup per unit of the normal map's slope
  /// (seed 003's refractionScale, seed value 0.1). Default 0 (flat float glass). [0, 1].
  float refraction_scale = 0.0f;
  /// Blend toward the colour texture (seed 003: 0.5). Default 0. [0, 1].
  float color_blend = 0.0f;
  /// Tangent-space normal map file (PNG/JPEG, tileable), "" = built-in (glass: gentle
  /// waviness; ice: frost facets). Tiled `texture_scale` times across the pane.
  std::string normal_map{};
  /// Colour texture file (sRGB PNG/JPEG), "" = built-in (glass: faint smudges; ice: frost).
  std::string color_texture{};
  /// Texture tiles across the pane (both textures). Default 1. [0.01, 1000].
  float texture_scale = 1.0f;
  /// Fresnel weighting. Default exact.
  GlassFresnel fresnel = GlassFresnel::exact;
  /// Exponent of the sun's highlight. Default 512. [1, 4096].
  float specular_power = 512.0f;
  /// Strength of the sun's highlight (weighted by Fresnel). 0 = none. Default 1. [0, 100].
  float specular_intensity = 1.0f;
  /// How many transmissive slabs one view ray passes through (the surface hit plus those
  /// behind it, traced analytically; see docs/glass.md "Stacked panes"). Default 3. [1, 4].
  int max_layers = 3;
  /// What the surfaces show. Default final.
  GlassDebugView debug_view = GlassDebugView::final;
};

/// Ice's defaults: IOR 1.31, procedural frost normal map and colour texture, roughness 0.15,
/// a slight blue tint and attenuation, 2 cm thick.
[[nodiscard]] GlassParams ice_defaults();
/// Seed 003's look from `base` (pane placement kept): no Fresnel, no thickness, the normal
/// map offset at 0.1 and a 50/50 blend with the colour texture.
[[nodiscard]] GlassParams glass_seed_preset(const GlassParams& base);

/// The glass or ice effect with its typed API.
class GlassEffect : public Effect {
public:
  /// Sets every parameter at once (validated; unchanged on error).
  [[nodiscard]] virtual Result<void> set_params(const GlassParams& params) = 0;
  /// The current parameters.
  [[nodiscard]] virtual const GlassParams& params() const = 0;
  /// How many surfaces it draws (the pane, if on, and the scene's transmissive objects).
  [[nodiscard]] virtual std::size_t surface_count() const = 0;
};

/// Creates a glass effect (GlassParams{} defaults, the "window" anchor, the scene's
/// transmissive objects). Errors: invalid_argument (no context, frames_in_flight outside
/// [1, 16], more than 64 transmissive objects), texture or Vulkan errors.
[[nodiscard]] Result<std::unique_ptr<GlassEffect>> create_glass(const EffectCreateInfo& info);
/// Creates an ice effect (ice_defaults()); otherwise as create_glass.
[[nodiscard]] Result<std::unique_ptr<GlassEffect>> create_ice(const EffectCreateInfo& info);
/// The parameter schemas ("glass", "ice").
[[nodiscard]] const ParamSchema& glass_schema();
[[nodiscard]] const ParamSchema& ice_schema();
/// Registers "glass" and "ice".
[[nodiscard]] Result<void> register_glass(EffectRegistry& registry);

} // namespace snell
