// The viewer's own Vulkan: a GLFW window, an instance with the window system's surface
// extensions, a validation messenger (synchronization validation included), the surface, and a
// device that can present to it. Snell adopts the instance, device and queue
// (snell::Context::adopt) and destroys none of them: the viewer is a host that owns its
// Vulkan, as samples/embed-host is, but one that presents to a swapchain.
#pragma once

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

struct GLFWwindow;

namespace snell::viewer {

/// Validation messages. Outlives every Vulkan object: the layer reports leaks up to and during
/// vkDestroyInstance. Errors and validation warnings fail a run; performance warnings (type
/// PERFORMANCE, e.g. a vertex attribute a plugin's shader does not read) are reported only, as
/// snell::Context counts them apart from errors.
struct ValidationLog {
  std::atomic<std::uint32_t> errors{0};
  std::atomic<std::uint32_t> warnings{0};    ///< Validation warnings (not performance).
  std::atomic<std::uint32_t> performance{0}; ///< Performance warnings.
  std::mutex mutex;
  std::vector<std::string> messages; ///< Every message, at most 100, oldest first.
  /// The messages that fail a run: errors and validation warnings.
  [[nodiscard]] std::uint32_t failures() const { return errors + warnings; }
};

/// How to create the window and the device.
struct HostOptions {
  std::uint32_t width = 1280; ///< Initial window size (screen coordinates).
  std::uint32_t height = 720;
  std::string title = "snell view";
  bool validation = false; ///< VK_LAYER_KHRONOS_validation + synchronization validation.
  /// "" (SNELL_DEVICE, else the best: discrete, integrated, virtual, CPU), "lavapipe"/"cpu",
  /// "gpu", or a case-insensitive substring of the device name (as `snell render --device`).
  std::string device;
};

/// The window, instance, surface, device and queue. Destroys them in reverse order; everything
/// created from the device must be gone by then. Move-less: the GLFW callbacks point at it.
class VulkanHost {
public:
  VulkanHost() = default;
  VulkanHost(const VulkanHost&) = delete;
  VulkanHost& operator=(const VulkanHost&) = delete;
  ~VulkanHost();

  /// Opens the window (GLFW, no client API) and creates everything. Errors: no display or no
  /// Vulkan-capable window system (missing_feature), no device that can present
  /// (no_device: lists the devices), Vulkan failures (vulkan_error). `log` must outlive this.
  [[nodiscard]] Result<void> init(const HostOptions& options, ValidationLog& log);

  /// A memory type allowed by `type_bits` with all of `flags`.
  [[nodiscard]] Result<std::uint32_t> memory_type(std::uint32_t type_bits,
                                                  VkMemoryPropertyFlags flags) const;

  GLFWwindow* window = nullptr;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE; ///< Graphics + compute + present.
  std::uint32_t queue_family = 0;
  std::string device_name;
  bool validation = false;
  VkPhysicalDeviceMemoryProperties memory{};
  /// The pNext chain the device was created with (for snell::AdoptInfo::enabled_features).
  [[nodiscard]] const void* enabled_features() const { return &features2_; }

private:
  bool glfw_ = false;
  VkPhysicalDeviceVulkan13Features features13_{};
  VkPhysicalDeviceVulkan11Features features11_{};
  VkPhysicalDeviceFeatures2 features2_{};
};

/// The GLFW error of the last failing call ("" when none), for messages.
[[nodiscard]] std::string glfw_error();

} // namespace snell::viewer
