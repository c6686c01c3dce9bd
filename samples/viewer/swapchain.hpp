// The viewer's swapchain: an sRGB surface format, FIFO (default) or mailbox, the images, their
// views and framebuffers for the UI render pass, and one "rendered" semaphore per image.
#pragma once

#include "vulkan_host.hpp"

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace snell::viewer {

/// What the swapchain is created with.
struct SwapchainDesc {
  bool mailbox = false; ///< VK_PRESENT_MODE_MAILBOX_KHR when supported (else FIFO). Default FIFO.
  /// Also TRANSFER_SRC (window screenshots) when the surface supports it. Default true.
  bool capture = true;
};

/// A swapchain and what belongs to each of its images (RAII, not movable).
///
/// Formats: the first of B8G8R8A8_SRGB, R8G8B8A8_SRGB, A8B8G8R8_SRGB_PACK32 with the
/// SRGB_NONLINEAR colour space that the surface offers, so shading results (linear) are encoded
/// by the hardware as in Snell's own rgba8_srgb targets. A surface without one is refused.
///
/// Semaphores: an image's "rendered" semaphore is signalled by the submission that draws into it
/// and waited on by its present. It is per image, not per frame in flight: once the image is
/// acquired again its previous present has consumed the semaphore, so it can be signalled anew
/// (a per-frame semaphore could still be waited on by a pending present).
class Swapchain {
public:
  Swapchain() = default;
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;
  ~Swapchain();

  /// Chooses the format (first call only; later calls keep it) and present mode and creates
  /// the swapchain for the window's current framebuffer size. Returns false, creating nothing,
  /// when that size is 0 x 0 (minimised). The previous swapchain is handed to the new one as
  /// `oldSwapchain` and then destroyed: the caller must have waited for every submission that
  /// used it. `render_pass` (may be VK_NULL_HANDLE on the first call to learn the format) is the
  /// one the framebuffers are made for.
  [[nodiscard]] Result<bool> create(const VulkanHost& host, const SwapchainDesc& desc,
                                    VkRenderPass render_pass);
  /// Framebuffers for `render_pass` (after create() with VK_NULL_HANDLE).
  [[nodiscard]] Result<void> make_framebuffers(VkRenderPass render_pass);
  /// Destroys everything (swapchain, views, framebuffers, semaphores).
  void destroy();

  [[nodiscard]] bool valid() const { return swapchain_ != VK_NULL_HANDLE; }
  [[nodiscard]] VkSwapchainKHR handle() const { return swapchain_; }
  [[nodiscard]] VkFormat format() const { return format_; }
  [[nodiscard]] VkExtent2D extent() const { return extent_; }
  [[nodiscard]] VkPresentModeKHR present_mode() const { return mode_; }
  /// Whether images can be copied from (window screenshots).
  [[nodiscard]] bool can_capture() const { return capture_; }
  [[nodiscard]] std::uint32_t image_count() const {
    return static_cast<std::uint32_t>(images_.size());
  }
  [[nodiscard]] std::uint32_t min_image_count() const { return min_images_; }
  [[nodiscard]] VkImage image(std::uint32_t i) const { return images_[i]; }
  [[nodiscard]] VkFramebuffer framebuffer(std::uint32_t i) const { return framebuffers_[i]; }
  [[nodiscard]] VkSemaphore rendered(std::uint32_t i) const { return rendered_[i]; }
  /// How many times the swapchain was (re)created.
  [[nodiscard]] std::uint32_t generation() const { return generation_; }

private:
  void destroy_image_objects();
  VkDevice device_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR color_space_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkExtent2D extent_{0, 0};
  VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
  bool capture_ = false;
  std::uint32_t min_images_ = 2;
  std::uint32_t generation_ = 0;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> rendered_;
};

/// The name of a present mode ("fifo", "mailbox", ...).
[[nodiscard]] const char* present_mode_name(VkPresentModeKHR mode);

} // namespace snell::viewer
