// The embed-host sample's own Vulkan: instance, validation messenger, device, queue, and the
// frame it renders into (colour + depth images, command buffer, fence, readback buffer). Nothing
// here uses Snell: this is what a host application already has before it meets Snell.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace embed {

/// The host's error style: its own Vulkan calls throw; Snell's calls return snell::Result.
struct HostError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws HostError naming `what` and the VkResult when `result` is not VK_SUCCESS.
void vk_check(VkResult result, const char* what);

/// Validation messages. Outlives every Vulkan object: the layer reports leaks up to and during
/// vkDestroyInstance.
struct ValidationLog {
  std::atomic<std::uint32_t> errors{0};
  std::atomic<std::uint32_t> warnings{0};
  std::mutex mutex;
  std::vector<std::string> messages; ///< Errors only, at most 100.
};

/// How to create the device.
struct DeviceOptions {
  bool validation = false; ///< VK_LAYER_KHRONOS_validation + synchronization validation.
  /// "" (best: discrete, integrated, virtual, CPU), "lavapipe"/"cpu" (CPU devices only), "gpu"
  /// (non-CPU only), or a case-insensitive substring of the device name.
  std::string device;
};

/// The host's instance, device and queue. Destroys them (device, messenger, instance) when it
/// goes; everything created from the device must be gone by then.
class HostDevice {
public:
  HostDevice() = default;
  HostDevice(const HostDevice&) = delete;
  HostDevice& operator=(const HostDevice&) = delete;
  ~HostDevice();

  /// Creates everything; throws HostError. `log` must outlive this object.
  void init(const DeviceOptions& options, ValidationLog& log);

  /// A memory type allowed by `type_bits` with all of `flags`; throws when there is none.
  [[nodiscard]] std::uint32_t memory_type(std::uint32_t type_bits,
                                          VkMemoryPropertyFlags flags) const;

  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  std::string device_name;
  VkPhysicalDeviceMemoryProperties memory{};
};

/// The host's output: a colour (R8G8B8A8_SRGB) and a depth (D32_SFLOAT) image, a command pool
/// and buffer, a fence, and a host-visible buffer the colour image is copied into.
class HostFrame {
public:
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  HostFrame() = default;
  HostFrame(const HostFrame&) = delete;
  HostFrame& operator=(const HostFrame&) = delete;
  ~HostFrame();

  /// Creates everything for `extent`; throws HostError. `device` must outlive this object.
  void init(const HostDevice& device, VkExtent2D extent);
  /// Submits the recorded command buffer, waits for its fence and resets it.
  void submit_and_wait();
  /// The colour image as copied by the last frame: RGBA8, sRGB-encoded, rows top first.
  [[nodiscard]] std::vector<std::uint8_t> pixels() const;

  VkExtent2D extent{0, 0};
  VkImage color = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkImageView color_view = VK_NULL_HANDLE;
  VkImageView depth_view = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkBuffer readback = VK_NULL_HANDLE;

private:
  const HostDevice* dev_ = nullptr;
  VkDeviceMemory color_memory_ = VK_NULL_HANDLE;
  VkDeviceMemory depth_memory_ = VK_NULL_HANDLE;
  VkDeviceMemory readback_memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

} // namespace embed
