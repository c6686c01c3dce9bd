// Snell plugin "dynamic_cubemap" (seed 002): a probe captures the scene around a point into a cube
// map every frame (six faces in one multiview pass, or the seed's six passes) and draws its
// owner, a reflecting or refracting sphere, from it. First step of the effect: capture, mips,
// the owner left out of its own capture, reflect / refract / glass surfaces with roughness.
// See docs/cubemap.md.
#pragma once

#include <snell/effect.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace snell {

/// How the six faces are drawn.
enum class CubemapCaptureMode : std::uint8_t {
  /// One pass, view mask 0b111111 (six views). Default. On a CPU device (lavapipe) the faces
  /// are drawn one by one instead: Mesa 22.3's lavapipe renders views 1..5 wrongly.
  multiview,
  six_pass, ///< Six passes, one per face (seed 002).
};

/// When the capture is refreshed. Whatever the policy, the first frame captures all six faces,
/// and the surface never samples a cube whose faces come from different refreshes. Under a
/// capture budget (EffectCreateInfo::capture_budget, shared by the host's probes) a due refresh
/// is drawn as far as the budget grants, into a back cube published when its six faces are done.
enum class CubemapRefresh : std::uint8_t {
  every_frame,     ///< All six faces every frame. Default.
  every_n,         ///< All six faces every `refresh_n` frames.
  on_demand,       ///< All six faces when DynamicCubemapEffect::request_update() asks.
  faces_per_frame, ///< `faces_per_frame` faces a frame into a back cube, published whole (with
                   ///< its mips) when its six faces are done (time slicing).
};

/// How the cube is filtered for rough lookups (`roughness` picks a level either way).
enum class CubemapPrefilter : std::uint8_t {
  none, ///< Level 0 only: sharp, `roughness` has no effect (cheapest).
  mips, ///< Box-filtered mip chain after every capture (a blur, not a GGX lobe). Default.
  ggx,  ///< The mips, then a compute pass convolving the cube with GGX per roughness level
        ///< (split-sum prefilter as Filament's and three.js's PMREM): level k holds roughness
        ///< k / (levels - 1) (snell::CubePrefilter, docs/runtime.md).
};

/// What the owner's surface shows.
enum class CubemapSurface : std::uint8_t {
  reflect, ///< A mirror: the capture along reflect(view, normal). Default.
  refract, ///< Through a solid sphere of `ior`: refracted in, across, and out again.
  glass,   ///< Both, weighted by exact dielectric Fresnel.
};

/// Parameters of the dynamic cube map. Every field documents its default and range; `snell list`
/// prints the same from the schema.
struct DynamicCubemapParams {
  /// Where the capture is taken and the sphere drawn, world units (m). Default: the scene's
  /// "probe" anchor, else (0, 1, 0). Each in [-1e4, 1e4].
  glm::vec3 center{0.0f, 1.0f, 0.0f};
  /// Name of the scene object (a glTF node) the probe is attached to: the capture is taken at
  /// the centre of its world bounds (`center` is then unused), the object is left out of its
  /// own capture, and the effect draws it with the probe's shading. "" = no object: the effect
  /// draws its own sphere (`center`, `radius`). Default: the "probe" anchor's object's name,
  /// else "". A name the scene does not have is refused.
  std::string node{};
  /// Radius of the sphere the effect draws when `node` is "", m. Default: half the "probe"
  /// anchor's size, else 0.5. [0.01, 1e4].
  float radius = 0.5f;
  /// Width = height of each cube face, pixels. Default 256 (seed 002). [16, 2048].
  int face_size = 256;
  /// Near and far distances of the capture, m. Defaults 0.05 and 200. z_near in [0.001, 100],
  /// z_far in [0.01, 1e5]; z_near < z_far is required when capturing.
  float z_near = 0.05f;
  float z_far = 200.0f;
  /// How the faces are drawn. Default multiview.
  CubemapCaptureMode capture = CubemapCaptureMode::multiview;
  /// When the capture is refreshed. Default every_frame.
  CubemapRefresh refresh = CubemapRefresh::every_frame;
  /// Frames between refreshes for every_n. Default 2. [1, 1000].
  int refresh_n = 2;
  /// Faces captured a frame for faces_per_frame. Default 1. [1, 6].
  int faces_per_frame = 1;
  /// Objects drawn into the capture (snell::layer bits). Default layer::captured (8): the owner
  /// of the probe has no `captured` bit and stays out of its own capture.
  int capture_layers = 8;
  /// What the surface shows. Default reflect.
  CubemapSurface surface = CubemapSurface::reflect;
  /// Index of refraction of the sphere for refract and glass (seed 002: air 1.0, water 1.33,
  /// glass 1.51). Default 1.51. [1, 3].
  float ior = 1.51f;
  /// Dispersion of refract and glass, 20 / Abbe number as KHR_materials_dispersion defines it:
  /// red, green and blue refract with snell::dispersion_iors(ior, dispersion). 0 = none
  /// (default; one lookup instead of three). [0, 2] (flint glass SF11: ~0.78).
  float dispersion = 0.0f;
  /// How the cube is filtered for `roughness`. Default mips.
  CubemapPrefilter prefilter = CubemapPrefilter::mips;
  /// Roughness of the surface: the lookup reads level roughness * (levels - 1) of the filtered
  /// cube (with prefilter = ggx, the GGX lobe of that perceptual roughness). 0 = a mirror.
  /// Default 0. [0, 1].
  float roughness = 0.0f;
  /// Box projection (parallax correction): the capture is taken as the inside of the world box
  /// box_min..box_max (a room), so a lookup is aimed at where the ray from the surface point
  /// leaves the box instead of treating the capture as infinitely far. Default false.
  bool box_projection = false;
  /// The room's corners, world units (m); box_min < box_max on every axis when box_projection
  /// is on. Defaults (-5, 0, -5) and (5, 5, 5). Each in [-1e4, 1e4].
  glm::vec3 box_min{-5.0f, 0.0f, -5.0f};
  glm::vec3 box_max{5.0f, 5.0f, 5.0f};
  /// Colour multiplying what the surface shows (a metal's reflectance), linear RGB. Default
  /// (1, 1, 1). Each in [0, 1].
  glm::vec3 tint{1.0f, 1.0f, 1.0f};
};

/// The dynamic cube map effect with its typed API.
class DynamicCubemapEffect : public Effect {
public:
  /// Sets every parameter at once (validated; unchanged on error).
  [[nodiscard]] virtual Result<void> set_params(const DynamicCubemapParams& params) = 0;
  /// The current parameters.
  [[nodiscard]] virtual const DynamicCubemapParams& params() const = 0;
  /// Asks for a full capture (refresh = on_demand; any policy accepts it): in the next frame,
  /// or, under a capture budget (EffectCreateInfo::capture_budget), as the stalest probe.
  virtual void request_update() = 0;
  /// How many complete cubes have been published so far (one per full capture, one per
  /// finished slice set): for tests and tools.
  [[nodiscard]] virtual std::uint64_t publications() const = 0;
  /// The faces drawn by the last record_passes(), one bit per face (bit f = CubeFace f): 0x3F
  /// for a full capture, fewer for a slice, 0 when nothing was due or granted.
  [[nodiscard]] virtual std::uint32_t faces_captured() const = 0;
};

/// Creates the effect. Errors: invalid_argument (no context, frames_in_flight outside [1, 16]),
/// Vulkan errors.
[[nodiscard]] Result<std::unique_ptr<DynamicCubemapEffect>>
create_dynamic_cubemap(const EffectCreateInfo& info);
/// The parameter schema ("dynamic_cubemap").
[[nodiscard]] const ParamSchema& dynamic_cubemap_schema();
/// Registers "dynamic_cubemap".
[[nodiscard]] Result<void> register_dynamic_cubemap(EffectRegistry& registry);

} // namespace snell
