// Snell plugins: the Effect interface, data-driven parameters with schemas, and the registry
// through which a host creates effects (DESIGN.md, "Plugins"). No globals, no static
// self-registration: the host owns an EffectRegistry and calls register_builtin_effects on it.
#pragma once

#include <snell/context.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/scene.hpp>
#include <snell/scene_source.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace snell {

/// An image an effect exposes for debugging (thumbnails, tests).
struct DebugTarget {
  std::string name;                  ///< "water.reflection", "depth", ...
  VkImageView view = VK_NULL_HANDLE; ///< 2D view, SHADER_READ_ONLY_OPTIMAL after the passes.
  bool depth = false;                ///< A depth image (visualised with a contrast curve).
  VkImage image = VK_NULL_HANDLE;    ///< The image itself (for readback in tests), if any.
  std::uint32_t width = 0;           ///< Size of level 0 in pixels.
  std::uint32_t height = 0;
  VkFormat format = VK_FORMAT_UNDEFINED; ///< Format of `image` (for readback).
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
};

/// A parameter value: bool, int, float, vec2/3/4 or string (enumerations and texture paths).
using ParamValue = std::variant<bool, int, float, glm::vec2, glm::vec3, glm::vec4, std::string>;

/// The name of a ParamType ("number", "vec3", ...).
[[nodiscard]] std::string_view to_string(ParamType type);
/// A value as text, in the form parse_param accepts ("0.5", "0,1", "oblique", "true").
[[nodiscard]] std::string to_string(const ParamValue& value);

/// One parameter's description.
struct ParamSpec {
  std::string name; ///< Key for set_param, e.g. "wave_height".
  ParamType type = ParamType::number;
  ParamValue default_value = 0.0f;  ///< Must equal the typed struct's default (tested).
  float min = 0.0f;                 ///< Inclusive lower bound (numbers, integers, vectors).
  float max = 0.0f;                 ///< Inclusive upper bound.
  std::vector<std::string> choices; ///< Valid values of an enumeration.
  std::string unit;                 ///< "m", "m/s", "1/m", "" for none.
  std::string doc;                  ///< One line: what it does.
};

/// An effect's parameters.
struct ParamSchema {
  std::string effect; ///< The registered name, e.g. "water".
  std::string doc;    ///< One line about the effect.
  std::vector<ParamSpec> params;
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

/// Per-frame information the host hands to every effect before recording.
struct FrameInfo {
  float time = 0.0f;         ///< Seconds since the start (animation). Default 0.
  SceneView main_view;       ///< The host's main view: matrices, eye, extent, formats.
  DirectionalLight light;    ///< The scene's light (for specular highlights).
  GpuTimer* timer = nullptr; ///< Optional: effects time their passes with it.
};

/// What an effect needs at creation.
struct EffectCreateInfo {
  const Context* context = nullptr; ///< Required; must outlive the effect.
  /// Formats of the host's main rendering, where record_draw draws.
  VkFormat color_format = VK_FORMAT_R8G8B8A8_SRGB;
  VkFormat depth_format = VK_FORMAT_D32_SFLOAT;
  /// Optional scene: effects read anchors ("water", "window", "probe") and the light from it.
  const Scene* scene = nullptr;
};

/// A reflection/refraction effect. Lifecycle per frame: update(info) → record_passes(cmd,
/// scene) outside any rendering → the host begins its main rendering → record_draw(cmd, info)
/// → the host ends it. Effects own their targets and recreate them when the extent changes.
class Effect {
public:
  virtual ~Effect() = default;
  /// The registered type name ("water").
  [[nodiscard]] virtual std::string_view type() const = 0;
  /// Sets one parameter. Errors: unknown key (lists the valid keys), wrong type, non-finite or
  /// out-of-range value (names parameter, value and range). Nothing is clamped silently.
  [[nodiscard]] virtual Result<void> set_param(std::string_view key, const ParamValue& value) = 0;
  /// Reads one parameter's current value (unknown key: the error lists the valid keys).
  [[nodiscard]] virtual Result<ParamValue> get_param(std::string_view key) const = 0;
  /// Per-frame state: camera, time, extent. Creates or resizes targets; a failure is kept in
  /// error() and the effect records nothing until a later update succeeds.
  virtual void update(const FrameInfo& info) = 0;
  /// Offscreen passes (outside any rendering), calling back into the host's scene.
  virtual void record_passes(VkCommandBuffer cmd, SceneSource& scene) = 0;
  /// The effect's surfaces, inside the host's main rendering.
  virtual void record_draw(VkCommandBuffer cmd, const FrameInfo& info) = 0;
  /// The effect's intermediate targets, for thumbnails and tests.
  [[nodiscard]] virtual std::span<const DebugTarget> debug_targets() const = 0;
  /// The last failure of update(), or nullptr.
  [[nodiscard]] virtual const Error* error() const = 0;
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
    EffectFactory factory;
    ParamSchema schema;
  };
  std::map<std::string, Entry, std::less<>> entries_;
};

/// Registers every plugin built into this Snell (water, ...). Defined by the plugins library
/// (`snell::effects`), generated from the plugins/ folders, so adding a plugin touches no runtime
/// code. Errors only if one of them is already registered.
[[nodiscard]] Result<void> register_builtin_effects(EffectRegistry& registry);

} // namespace snell
