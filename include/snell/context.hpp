// Snell runtime: the Vulkan context. Either creates a headless instance + device, or adopts the
// host's objects without taking ownership (Dear ImGui backend style: one init struct, no globals).
#pragma once

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace snell {

/// Description of one physical device, as `snell info` prints it.
struct DeviceInfo {
  std::string name{}; ///< VkPhysicalDeviceProperties::deviceName.
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER; ///< Discrete, integrated, CPU, ...
  std::uint32_t api_version = 0;                             ///< Vulkan version the driver reports.
  std::string driver{};                                      ///< Driver name and info.
  float timestamp_period_ns = 0.0f; ///< Nanoseconds per timestamp tick (0: no timestamps).
  bool suitable = false;            ///< Meets Snell's requirements (see `missing`).
  std::string missing{};            ///< Why it is not suitable (empty when suitable).
};

/// Options for Context::create. Every field has a default that works headless.
struct ContextDesc {
  /// Enable VK_LAYER_KHRONOS_validation with synchronization validation and count its errors.
  /// Default false; the environment variable SNELL_VALIDATION=1 turns it on too.
  bool validation = false;
  /// Which device: "" (default: the SNELL_DEVICE environment variable, else the best device:
  /// discrete GPU, then integrated, then virtual, then CPU), "lavapipe" (Mesa's CPU driver),
  /// "gpu" (any non-CPU device), or a case-insensitive substring of the device name.
  std::string device{};
  /// Application name reported to the driver. Default "snell".
  std::string app_name = "snell";
};

/// The host's Vulkan objects for Context::adopt. Snell uses them and destroys none of them. The
/// device must have been created with Vulkan 1.3 and the features Snell needs enabled:
/// dynamicRendering, synchronization2 (1.3), multiview (1.1) and shaderClipDistance (1.0).
struct AdoptInfo {
  VkInstance instance = VK_NULL_HANDLE;              ///< Required.
  VkPhysicalDevice physical_device = VK_NULL_HANDLE; ///< Required.
  VkDevice device = VK_NULL_HANDLE;                  ///< Required.
  VkQueue queue = VK_NULL_HANDLE; ///< Required: supports graphics, compute and transfer.
  std::uint32_t queue_family = 0; ///< Family index of `queue`. Default 0.
  /// Optional: the pNext chain the host passed to vkCreateDevice (VkPhysicalDeviceFeatures2,
  /// VkPhysicalDeviceVulkan11/13Features, ...). When given, adopt() checks that the features
  /// Snell needs are *enabled* in it, not only supported, and names any that is not. Default
  /// nullptr: only support is checked (Vulkan cannot query a device's enabled features).
  const void* enabled_features = nullptr;
};

/// The samplers every effect shares: created with the Context, destroyed with it.
enum class StandardSampler : std::uint8_t {
  linear_clamp,  ///< Bilinear within a level, linear between levels, clamp to edge: targets,
                 ///< snapshots, anything sampled by projection.
  linear_repeat, ///< Trilinear, repeat: tiling textures such as normal maps.
  nearest_clamp, ///< Nearest texel, level 0 only, clamp to edge: depth images, exact reads.
};
/// Number of StandardSampler values.
inline constexpr std::uint32_t kStandardSamplerCount = 3;

/// The Context's internal state (opaque to users; defined inside the runtime).
struct ContextState;

/// Owns (or borrows) the instance, device and queue that every Snell object uses.
/// Move-only. Every resource created from a Context must be destroyed before it.
class Context {
public:
  /// Creates a headless instance and device. Errors: no_device (none matches `desc.device`; the
  /// message lists the devices), missing_feature (names the feature), vulkan_error.
  [[nodiscard]] static Result<Context> create(const ContextDesc& desc = {});
  /// Adopts the host's objects. Checks that the required features are enabled on the device's
  /// physical device and that the queue family supports graphics + compute.
  [[nodiscard]] static Result<Context> adopt(const AdoptInfo& info);
  /// Lists the devices of a temporary instance (for `snell info`).
  [[nodiscard]] static Result<std::vector<DeviceInfo>> enumerate_devices();

  Context(Context&&) noexcept;
  Context& operator=(Context&&) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();

  [[nodiscard]] VkInstance instance() const;
  [[nodiscard]] VkPhysicalDevice physical_device() const;
  [[nodiscard]] VkDevice device() const;
  [[nodiscard]] VkQueue queue() const;
  [[nodiscard]] std::uint32_t queue_family() const;
  [[nodiscard]] const DeviceInfo& device_info() const;
  /// The physical device's limits (minUniformBufferOffsetAlignment, maxImageDimension2D, ...).
  [[nodiscard]] const VkPhysicalDeviceLimits& limits() const;
  /// One of the shared samplers (never VK_NULL_HANDLE on a valid context).
  [[nodiscard]] VkSampler sampler(StandardSampler which) const;
  /// True when this context owns the instance and device (created, not adopted).
  [[nodiscard]] bool owns_device() const;

  /// Whether the validation layer is active on this context.
  [[nodiscard]] bool validation_enabled() const;
  /// Number of validation errors (and of warnings) reported so far.
  [[nodiscard]] std::uint32_t validation_error_count() const;
  [[nodiscard]] std::uint32_t validation_warning_count() const;
  /// The messages of all validation errors and warnings so far, oldest first.
  [[nodiscard]] std::vector<std::string> validation_messages() const;

  /// Records commands with `record` into a one-time command buffer, submits it and waits.
  /// Thread-safe (one submit at a time). Errors: a call from inside `record` on the same thread
  /// (invalid_argument: it would wait forever), Vulkan failures (vulkan_error with the VkResult).
  [[nodiscard]] Result<void>
  submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const;

  /// Index of a memory type allowed by `type_bits` with all of `properties`, or an error.
  [[nodiscard]] Result<std::uint32_t> find_memory_type(std::uint32_t type_bits,
                                                       VkMemoryPropertyFlags properties) const;

private:
  /// The runtime's access to the state (resources keep a pointer to it: it survives moves).
  friend const ContextState* context_state(const Context& ctx) noexcept;
  explicit Context(std::unique_ptr<ContextState> state);
  std::unique_ptr<ContextState> impl_;
};

} // namespace snell
