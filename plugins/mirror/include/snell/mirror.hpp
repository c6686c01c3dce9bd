// Snell plugin "mirror": a planar mirror (three.js's Reflector, Babylon.js's MirrorTexture, the
// classic Vulkan offscreen sample) built on the plugin toolkit: the host's scene seen from the
// mirrored camera into a target at `resolution_scale`, scissored to the mirror on screen,
// clipped at the plane, then a surface with metal tint or dielectric Fresnel, roughness blur that
// hardens where objects touch the mirror, and a fade with distance. See docs/mirror.md.
#pragma once

#include <snell/effect.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace snell {

/// How the reflection pass keeps only what is in front of the mirror.
enum class MirrorClip : std::uint8_t {
  oblique,       ///< Lengyel's oblique near plane (no per-vertex cost). Default.
  clip_distance, ///< gl_ClipDistance against the plane.
};

/// How much the surface reflects.
enum class MirrorFresnel : std::uint8_t {
  none,       ///< A metal: the reflection times `tint` everywhere. Default.
  dielectric, ///< Exact dielectric Fresnel with `ior` over `base_color` (glass, water, lacquer).
};

/// Parameters of the mirror. Every field documents its default and range; `snell list` prints
/// the same from the schema. Distances in metres, colours linear RGB in [0, 1].
struct MirrorParams {
  /// Name of the scene object (a glTF node) whose mesh is the mirror: its plane is fitted to the
  /// mesh in world space (a mesh that is not planar within 0.1 % of its size, at least 0.1 mm,
  /// is refused, naming the node and how far it is off), the effect draws it, and its own
  /// reflection pass leaves it out (clipped 1 mm in front of the plane). "" = the effect's own
  /// rectangle (`center`, `normal`, `up`, `size`). Default: the "mirror" anchor's object's name,
  /// else "".
  std::string node{};
  /// Centre of the effect's own rectangle, m. Default: the "mirror" anchor's position, else
  /// (0, 1, 0). Each in [-1e4, 1e4].
  glm::vec3 center{0.0f, 1.0f, 0.0f};
  /// The side the rectangle reflects (normalised internally). (0, 0, 0) turns it toward the eye
  /// (as glass's pane: a schema range cannot exclude zero, so zero has a meaning). Default
  /// (0, 0, 1) (a wall mirror facing +Z). Each in [-1, 1].
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  /// The rectangle's "up" in world space, projected onto its plane. Zero or along `normal`:
  /// world +Y projected, or +Z for a horizontal mirror. Default (0, 1, 0). Each in [-1, 1].
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  /// Width (along cross(up, normal), the rectangle's right) and height (along `up`) of the
  /// rectangle, m. Default (2, 2). Each in [0.01, 1e4].
  glm::vec2 size{2.0f, 2.0f};
  /// Size of the reflection target relative to the output, per axis. Default 0.5. [0.1, 2].
  float resolution_scale = 0.5f;
  /// How the pass is clipped at the plane. Default oblique.
  MirrorClip clip = MirrorClip::oblique;
  /// Objects drawn in the reflection (snell::layer bits). Default layer::reflected (2). [0, 255].
  int reflection_layers = 2;
  /// Reflectance per channel (a metal's colour): multiplies the reflection. Default (0.95, 0.95,
  /// 0.95) (silver). Each in [0, 1].
  glm::vec3 tint{0.95f, 0.95f, 0.95f};
  /// Metal (none) or dielectric Fresnel. Default none.
  MirrorFresnel fresnel = MirrorFresnel::none;
  /// Index of refraction for fresnel = dielectric (glass 1.5, water 1.33). Default 1.5. [1, 3].
  float ior = 1.5f;
  /// Colour under the reflection: what a dielectric shows where it does not reflect, and what
  /// the reflection fades to. Default (0.02, 0.02, 0.02). Each in [0, 1].
  glm::vec3 base_color{0.02f, 0.02f, 0.02f};
  /// Roughness: the reflection blurs with roughness² times the reflected point's height above
  /// the plane (contact hardening: what touches the mirror stays sharp), read from the
  /// reflection pass's depth and the target's mip chain. 0 = a perfect mirror. Default 0. [0, 1].
  float roughness = 0.0f;
  /// The reflection fades to `base_color` as the reflected point's height above the plane
  /// reaches this distance, m (linearly). 0 = no fade (default). [0, 1e4].
  float fade_distance = 0.0f;
  /// Tangent-space normal map (PNG/JPEG, tileable) that distorts the reflection, "" = none
  /// (default).
  std::string normal_map{};
  /// Screen-space (uv) offset of the reflection lookup per unit of the normal map's slope.
  /// Default 0.02. [0, 0.2].
  float distortion = 0.02f;
  /// Normal-map tiles per unit of the mesh's uv (the rectangle's uv spans it once, so: tiles
  /// across it). Default 1. [0.01, 1000].
  float normal_tiles = 1.0f;
  /// What the back of the mirror shows (the camera behind the plane: no reflection is drawn).
  /// Default (0.2, 0.2, 0.2). Each in [0, 1].
  glm::vec3 back_color{0.2f, 0.2f, 0.2f};
};

/// What a host needs to sample the reflection in its own material (shaders/snell/mirror.glsl).
struct MirrorHostView {
  VkImageView color = VK_NULL_HANDLE; ///< The reflection (all mips), SHADER_READ_ONLY_OPTIMAL.
  VkSampler sampler = VK_NULL_HANDLE; ///< Trilinear, clamp to edge.
  /// World position -> reflection uv (homogeneous: divide by w): clip_to_uv(vulkan) times the
  /// reflection pass's projection and mirrored view. On the mirror's plane it equals the main
  /// view's screen uv. Valid for the frame after record_passes().
  glm::mat4 texture_matrix{1.0f};
  glm::vec4 plane{0.0f, 1.0f, 0.0f, 0.0f}; ///< The mirror's plane (xyz unit normal, w offset).
  std::uint32_t mip_levels = 1;            ///< Levels of `color`.
  bool drawn = false; ///< False when the pass was skipped (camera behind the mirror).
};

/// The mirror effect with its typed API.
class MirrorEffect : public Effect {
public:
  /// Sets every parameter at once (validated; unchanged on error).
  [[nodiscard]] virtual Result<void> set_params(const MirrorParams& params) = 0;
  /// The current parameters.
  [[nodiscard]] virtual const MirrorParams& params() const = 0;
  /// The mirror's world plane this frame (after update()): xyz the unit normal toward the
  /// reflecting side, w the offset (dot(normal, p) + w = 0 on the plane).
  [[nodiscard]] virtual glm::vec4 plane() const = 0;
  /// The reflection for a host's own material (after record_passes()).
  [[nodiscard]] virtual MirrorHostView host_view() const = 0;
};

/// Creates the effect. Errors: invalid_argument (no context, frames_in_flight outside [1, 16], a
/// "mirror" anchor's object that is not planar), Vulkan errors.
[[nodiscard]] Result<std::unique_ptr<MirrorEffect>> create_mirror(const EffectCreateInfo& info);
/// The parameter schema ("mirror").
[[nodiscard]] const ParamSchema& mirror_schema();
/// Registers "mirror".
[[nodiscard]] Result<void> register_mirror(EffectRegistry& registry);

} // namespace snell
