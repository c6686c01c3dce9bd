// Internal: the state behind snell::Context.
#pragma once

#include <snell/context.hpp>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace snell {

/// The state behind snell::Context (stable across moves: resources keep a pointer to it).
struct ContextState {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  bool owns = false;
  DeviceInfo info;
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceLimits limits{};
  VkSampler samplers[kStandardSamplerCount] = {}; ///< Indexed by StandardSampler.

  // Validation (owned instances only).
  bool validation = false;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  std::atomic<std::uint32_t> errors{0};
  std::atomic<std::uint32_t> warnings{0};
  mutable std::mutex messages_mutex;
  std::vector<std::string> messages;

  // One-shot submissions.
  VkCommandPool pool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  mutable std::mutex submit_mutex;
  /// The thread inside submit_and_wait (a nested call from its callback is refused, not a
  /// deadlock).
  mutable std::atomic<std::thread::id> submit_owner{};

  ~ContextState();

  /// See Context::submit_and_wait / Context::find_memory_type.
  Result<void> submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const;
  Result<std::uint32_t> find_memory_type(std::uint32_t type_bits,
                                         VkMemoryPropertyFlags properties) const;
};

/// The state of `ctx` (never null for a valid context).
const ContextState* context_state(const Context& ctx) noexcept;

} // namespace snell
