// Snell plugins, the host-facing API: the Effect interface, data-driven parameters with schemas,
// and the registry through which a host creates effects (DESIGN.md, "Plugins"). No globals, no
// static self-registration: the host owns an EffectRegistry and calls register_builtin_effects
// on it. C++17; it includes neither the scene model nor the plugin-authoring toolkit (those are
// snell/scene.hpp and snell/plugin.hpp).
#pragma once

#include <snell/result.hpp>
#include <snell/scene_source.hpp>
#include <snell/scene_types.hpp>
#include <snell/span.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace snell {

class CaptureBudget;
class Context;
class GpuTimer;
class ProbeDirectory;
class SceneSnapshot;
struct Scene;

/// What a DebugTarget shows.
enum class DebugKind : std::uint8_t {
  color,     ///< Level 0 of a colour image.
  depth,     ///< A depth image (shown with a contrast curve).
  cube_face, ///< One face (`layer`) of a cube image.
  mip_level, ///< One mip level (`mip`) of a colour image.
};

/// An image an effect exposes for debugging (overlay thumbnails, tests).
struct DebugTarget {
  std::string name{};                ///< "water.reflection", "probe.face+x", ...
  DebugKind kind = DebugKind::color; ///< What `view` shows. Default color.
  /// A 2D view of exactly the level and layer shown, in SHADER_READ_ONLY_OPTIMAL whenever
  /// debug_targets() may be read (toolkit targets are, from creation on).
  VkImageView view = VK_NULL_HANDLE;
  VkImage image = VK_NULL_HANDLE;        ///< The image itself (for readback in tests), if any.
  std::uint32_t width = 0;               ///< Width of the level shown, pixels.
  std::uint32_t height = 0;              ///< Height of the level shown, pixels.
  VkFormat format = VK_FORMAT_UNDEFINED; ///< Format of `image` (for readback).
  std::uint32_t layer = 0;               ///< Array layer / cube face shown. Default 0.
  std::uint32_t mip = 0;                 ///< Mip level shown. Default 0.
};

/// Types a parameter can have.
enum class ParamType : std::uint8_t {
  boolean,     ///< bool
  integer,     ///< int (also bit masks)
  number,      ///< float
  enumeration, ///< std::string, one of ParamSpec::choices
  vec2,        ///< glm::vec2 (components each within [min, max])
  vec3,        ///< glm::vec3
  vec4,        ///< glm::vec4
  color,       ///< glm::vec3, linear RGB, each within [0, 1]
  texture,     ///< std::string: a file path (PNG/JPEG), "" for the built-in default
  string, ///< std::string: any text the effect gives a meaning to (a glTF node name); "" = none
};

/// A parameter value: bool, int, float, vec2/3/4 or string (enumerations and texture paths).
using ParamValue = std::variant<bool, int, float, glm::vec2, glm::vec3, glm::vec4, std::string>;

/// The name of a ParamType ("number", "vec3", ...).
[[nodiscard]] std::string_view to_string(ParamType type);
/// A value as text, in the form parse_param accepts ("0.5", "0,1", "oblique", "true").
[[nodiscard]] std::string to_string(const ParamValue& value);

/// One parameter's description.
struct ParamSpec {
  std::string name{}; ///< Key for set_param, e.g. "wave_height".
  ParamType type = ParamType::number;
  ParamValue default_value = 0.0f;    ///< Must equal the typed struct's default (tested).
  float min = 0.0f;                   ///< Inclusive lower bound (numbers, integers, vectors).
  float max = 0.0f;                   ///< Inclusive upper bound.
  std::vector<std::string> choices{}; ///< Valid values of an enumeration.
  std::string unit{};                 ///< "m", "m/s", "1/m", "" for none.
  std::string doc{};                  ///< One line: what it does.
};

/// An effect's parameters.
struct ParamSchema {
  std::string effect{}; ///< The registered name, e.g. "water".
  std::string doc{};    ///< One line about the effect.
  std::vector<ParamSpec> params{};
  /// The parameter called `name`, or nullptr.
  [[nodiscard]] const ParamSpec* find(std::string_view name) const;
  /// "a, b, c": every key (for error messages).
  [[nodiscard]] std::string key_list() const;
};

/// Checks `value` against `spec`: type, finiteness, range, enumeration choice. Errors name the
/// effect, the parameter, the value and the valid range; nothing is clamped.
[[nodiscard]] Result<void> validate_param(const ParamSchema& schema, const ParamSpec& spec,
                                          const ParamValue& value);
/// Parses text for `spec` ("0.5", "1,0", "0.2,0.4,0.6", "true", "oblique") and validates it.
[[nodiscard]] Result<ParamValue> parse_param(const ParamSchema& schema, const ParamSpec& spec,
                                             std::string_view text);

/// Per-frame information the host hands to every effect (update, record_passes, record_draw).
struct FrameInfo {
  float time = 0.0f; ///< Seconds since the start (animation). Default 0.
  /// The host's frame counter: +1 per frame, never reused. Resources an effect replaces while
  /// recording frame N are destroyed once frame N + frames_in_flight is recorded (the host's
  /// fence for frame N has then been waited on). Default 0.
  std::uint64_t frame_index = 0;
  SceneView main_view{};     ///< The host's main view: matrices, eye, extent, formats.
  DirectionalLight light{};  ///< The scene's light (for specular highlights).
  GpuTimer* timer = nullptr; ///< Optional: effects time their passes with it. Default none.
  /// The host's scene snapshot, set for the whole frame (update, record_passes, record_draw)
  /// when the host copies one for effects that want it (Effect::wants_snapshot); its images
  /// hold this frame's opaque colour (with mips) and depth in record_draw. nullptr when the
  /// host takes none: effects then render their own pass instead. Default none.
  const SceneSnapshot* snapshot = nullptr;
};

/// What an effect needs at creation.
struct EffectCreateInfo {
  const Context* context = nullptr; ///< Required; must outlive the effect.
  /// Formats of the host's main rendering, where record_draw draws.
  VkFormat color_format = VK_FORMAT_R8G8B8A8_SRGB; ///< Default R8G8B8A8_SRGB.
  VkFormat depth_format = VK_FORMAT_D32_SFLOAT;    ///< Default D32_SFLOAT.
  /// How many frames the host may have recorded and not yet waited for: sizes per-frame
  /// uniform rings and delays the destruction of replaced resources. 1..16. Default 2.
  std::uint32_t frames_in_flight = 2;
  /// Optional scene: effects read anchors ("water", "window", "probe"), nodes and the light from
  /// it. Must outlive the effect. Default none.
  const Scene* scene = nullptr;
  /// Optional: the host's per-frame budget of cube-face captures, shared by every probe it is
  /// given to (dynamic_cubemap): stalest and nearest probes first, each cube published whole.
  /// Must outlive the effect. Default none: each probe follows its own refresh policy.
  CaptureBudget* capture_budget = nullptr;
  /// Optional: the host's list of published probes. Probes (dynamic_cubemap) publish their
  /// cubes in it; glass reflects the nearest one instead of the sky. Must outlive the effect.
  /// Default none.
  ProbeDirectory* probes = nullptr;
};

/// A reflection/refraction effect. Per frame, in the phases of DESIGN.md ("Frame phases"):
///   1. update(info): camera, time, extent; creates or resizes targets. On error the host skips
///      this effect for the frame (nothing of it is recorded) and reports the error.
///   2. offscreen: record_passes(cmd, info, scene) outside any rendering.
///   3. opaque: the host draws its scene into its main colour + depth (leaving out the objects
///      drawn_objects() and replaced_objects() name), then ends that rendering.
///   4. snapshot: when an effect wants_snapshot(), the host copies colour + depth once
///      (SceneSnapshot::record) and passes it in FrameInfo::snapshot.
///   5. surfaces: inside the host's main rendering again (colour + depth loaded),
///      record_draw(cmd, info).
///   6. overlay: debug thumbnails of debug_targets().
/// Replaced resources are destroyed frames_in_flight frames later; effects never idle the
/// host's device. Destroy an effect only after the GPU finished the frames that used it.
class Effect {
public:
  virtual ~Effect() = default;
  /// The registered type name ("water").
  [[nodiscard]] virtual std::string_view type() const = 0;
  /// Sets one parameter. Errors: unknown key (lists the valid keys), wrong type, non-finite or
  /// out-of-range value (names effect.key, value and range). Nothing is clamped silently, and
  /// nothing changes on error.
  [[nodiscard]] virtual Result<void> set_param(std::string_view key, const ParamValue& value) = 0;
  /// Reads one parameter's current value (unknown key: the error lists the valid keys).
  [[nodiscard]] virtual Result<ParamValue> get_param(std::string_view key) const = 0;
  /// Phase 1: per-frame state (camera, time, extent); creates or resizes targets.
  [[nodiscard]] virtual Result<void> update(const FrameInfo& info) = 0;
  /// Phase 2: offscreen passes (outside any rendering), drawing the host's scene through
  /// `scene`, timed with `info.timer` when given.
  [[nodiscard]] virtual Result<void> record_passes(VkCommandBuffer cmd, const FrameInfo& info,
                                                   SceneSource& scene) = 0;
  /// Phase 5: the effect's surfaces, inside the host's main rendering (formats of
  /// EffectCreateInfo); may sample `info.snapshot`.
  [[nodiscard]] virtual Result<void> record_draw(VkCommandBuffer cmd, const FrameInfo& info) = 0;
  /// The effect's intermediate targets, for thumbnails and tests (after update()).
  [[nodiscard]] virtual Span<const DebugTarget> debug_targets() const = 0;
  /// True when record_draw samples FrameInfo::snapshot this frame (the host then records one
  /// SceneSnapshot copy, shared by every effect). Default false.
  [[nodiscard]] virtual bool wants_snapshot() const { return false; }
  /// True when record_draw also samples the snapshot colour's levels above 0 (frosted glass):
  /// the host then builds the mip chain this frame (SnapshotSource::mips). Default false: only
  /// level 0 and depth are copied, the cheapest snapshot.
  [[nodiscard]] virtual bool wants_snapshot_mips() const { return false; }
  /// The pixels of the main view that record_draw samples from the snapshot this frame (valid
  /// after update()), margins for distortion included: the host copies only the union of the
  /// effects' regions (SnapshotSource::region). Extent 0 x 0 (default): the whole image.
  [[nodiscard]] virtual VkRect2D snapshot_region() const { return {}; }
  /// Objects of EffectCreateInfo::scene (indices into Scene::objects) that this effect draws
  /// itself with its own shading: the host's scene renderer leaves them out. Default none.
  [[nodiscard]] virtual Span<const int> drawn_objects() const { return {}; }
  /// Objects of EffectCreateInfo::scene that this effect covers in the main view with its own
  /// shading (phase 5) while they stay in every effect pass (a mirror's node: other mirrors and
  /// probes still see it): the host leaves them out of its opaque pass only (phase 3), so their
  /// pixels are not shaded twice. Leaving them in is correct too, only slower. Default none.
  [[nodiscard]] virtual Span<const int> replaced_objects() const { return {}; }
};

/// Creates an effect.
using EffectFactory = std::function<Result<std::unique_ptr<Effect>>(const EffectCreateInfo&)>;

/// Owned by the host: effect names → factories and schemas.
class EffectRegistry {
public:
  /// Registers `name`. Errors: duplicate_name when it exists, invalid_argument for an empty name
  /// or factory, or a schema whose defaults fail their own validation.
  [[nodiscard]] Result<void> add(std::string name, EffectFactory factory, ParamSchema schema);
  /// Creates the effect `name`. Unknown names: unknown_name listing the registered names.
  [[nodiscard]] Result<std::unique_ptr<Effect>> create(std::string_view name,
                                                       const EffectCreateInfo& info) const;
  /// The registered names, sorted.
  [[nodiscard]] std::vector<std::string> names() const;
  /// The schema of `name`, or nullptr.
  [[nodiscard]] const ParamSchema* schema(std::string_view name) const;

private:
  struct Entry {
    EffectFactory factory{};
    ParamSchema schema{};
  };
  std::map<std::string, Entry, std::less<>> entries_;
};

/// Registers every plugin built into this Snell (water, ...). Defined by the plugins library
/// (`snell::effects`), generated from the plugins/ folders, so adding a plugin touches no runtime
/// code. Errors only if one of them is already registered.
[[nodiscard]] Result<void> register_builtin_effects(EffectRegistry& registry);

} // namespace snell
