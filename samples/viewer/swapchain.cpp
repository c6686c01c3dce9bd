#include "swapchain.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <string>

namespace snell::viewer {
namespace {

Error vk_failure(const std::string& what, VkResult result) {
  Error e{ErrorCode::vulkan_error,
          what + " failed (VkResult " + std::to_string(static_cast<int>(result)) + ")"};
  e.vk_result = result;
  return e;
}

} // namespace

const char* present_mode_name(VkPresentModeKHR mode) {
  switch (mode) {
  case VK_PRESENT_MODE_FIFO_KHR:
    return "fifo";
  case VK_PRESENT_MODE_MAILBOX_KHR:
    return "mailbox";
  case VK_PRESENT_MODE_IMMEDIATE_KHR:
    return "immediate";
  case VK_PRESENT_MODE_FIFO_RELAXED_KHR:
    return "fifo_relaxed";
  default:
    return "other";
  }
}

Result<bool> Swapchain::create(const VulkanHost& host, const SwapchainDesc& desc,
                               VkRenderPass render_pass) {
  device_ = host.device;
  int fb_width = 0, fb_height = 0;
  glfwGetFramebufferSize(host.window, &fb_width, &fb_height);
  VkSurfaceCapabilitiesKHR caps{};
  if (VkResult r =
          vkGetPhysicalDeviceSurfaceCapabilitiesKHR(host.physical_device, host.surface, &caps);
      r != VK_SUCCESS) {
    return vk_failure("vkGetPhysicalDeviceSurfaceCapabilitiesKHR", r);
  }
  // The extent: the surface's when it dictates one, else the window's framebuffer size.
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) {
    extent.width = std::clamp(static_cast<std::uint32_t>(std::max(fb_width, 0)),
                              caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(static_cast<std::uint32_t>(std::max(fb_height, 0)),
                               caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0 || fb_width == 0 || fb_height == 0) {
    return false; // minimised: nothing to present to
  }

  if (format_ == VK_FORMAT_UNDEFINED) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(host.physical_device, host.surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(host.physical_device, host.surface, &count,
                                         formats.data());
    std::string offered;
    for (const VkFormat wanted :
         {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_A8B8G8R8_SRGB_PACK32}) {
      for (const VkSurfaceFormatKHR& f : formats) {
        if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR &&
            format_ == VK_FORMAT_UNDEFINED) {
          format_ = f.format;
          color_space_ = f.colorSpace;
        }
      }
    }
    if (format_ == VK_FORMAT_UNDEFINED) {
      for (const VkSurfaceFormatKHR& f : formats) {
        offered.append(offered.empty() ? "" : ", ")
            .append(std::to_string(static_cast<int>(f.format)));
      }
      return fail(ErrorCode::unsupported,
                  "the window's surface offers no 8-bit sRGB format with the sRGB colour space "
                  "(VkFormats offered: " +
                      offered + ")");
    }
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(host.physical_device, format_, &props);
    if ((props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT) == 0) {
      return fail(ErrorCode::unsupported, "the swapchain format (VkFormat " +
                                              std::to_string(static_cast<int>(format_)) +
                                              ") cannot be a blit destination");
    }
  }

  mode_ = VK_PRESENT_MODE_FIFO_KHR; // always supported
  if (desc.mailbox) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceSurfacePresentModesKHR(host.physical_device, host.surface, &count, nullptr);
    std::vector<VkPresentModeKHR> modes(count);
    vkGetPhysicalDeviceSurfacePresentModesKHR(host.physical_device, host.surface, &count,
                                              modes.data());
    if (std::find(modes.begin(), modes.end(), VK_PRESENT_MODE_MAILBOX_KHR) != modes.end()) {
      mode_ = VK_PRESENT_MODE_MAILBOX_KHR;
    }
  }
  // One image more than the minimum, so that acquiring rarely waits for the presentation
  // engine; mailbox needs at least three to replace queued images.
  std::uint32_t images =
      std::max(caps.minImageCount + 1, mode_ == VK_PRESENT_MODE_MAILBOX_KHR ? 3u : 2u);
  if (caps.maxImageCount != 0) {
    images = std::min(images, caps.maxImageCount);
  }
  min_images_ = std::max(caps.minImageCount, 2u);
  capture_ = desc.capture && (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;

  VkSwapchainCreateInfoKHR ci{};
  ci.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
  ci.surface = host.surface;
  ci.minImageCount = images;
  ci.imageFormat = format_;
  ci.imageColorSpace = color_space_;
  ci.imageExtent = extent;
  ci.imageArrayLayers = 1;
  ci.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                  (capture_ ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT} : 0u);
  ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ci.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR) != 0
                        ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                        : caps.currentTransform;
  ci.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR) != 0
                          ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                          : VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
  ci.presentMode = mode_;
  ci.clipped = VK_TRUE;
  ci.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  if (VkResult r = vkCreateSwapchainKHR(device_, &ci, nullptr, &created); r != VK_SUCCESS) {
    return vk_failure("vkCreateSwapchainKHR", r);
  }
  destroy(); // the old one (retired by oldSwapchain) and its images' objects
  swapchain_ = created;
  extent_ = extent;
  ++generation_;

  std::uint32_t count = 0;
  vkGetSwapchainImagesKHR(device_, swapchain_, &count, nullptr);
  images_.resize(count);
  vkGetSwapchainImagesKHR(device_, swapchain_, &count, images_.data());
  for (VkImage image : images_) {
    VkImageViewCreateInfo vi{};
    vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format_;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    if (VkResult r = vkCreateImageView(device_, &vi, nullptr, &view); r != VK_SUCCESS) {
      return vk_failure("vkCreateImageView (swapchain)", r);
    }
    views_.push_back(view);
    VkSemaphoreCreateInfo si{};
    si.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore semaphore = VK_NULL_HANDLE;
    if (VkResult r = vkCreateSemaphore(device_, &si, nullptr, &semaphore); r != VK_SUCCESS) {
      return vk_failure("vkCreateSemaphore (swapchain)", r);
    }
    rendered_.push_back(semaphore);
  }
  if (render_pass != VK_NULL_HANDLE) {
    SNELL_TRY(make_framebuffers(render_pass));
  }
  return true;
}

Result<void> Swapchain::make_framebuffers(VkRenderPass render_pass) {
  for (VkFramebuffer fb : framebuffers_) {
    vkDestroyFramebuffer(device_, fb, nullptr);
  }
  framebuffers_.clear();
  for (VkImageView view : views_) {
    VkFramebufferCreateInfo fi{};
    fi.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fi.renderPass = render_pass;
    fi.attachmentCount = 1;
    fi.pAttachments = &view;
    fi.width = extent_.width;
    fi.height = extent_.height;
    fi.layers = 1;
    VkFramebuffer fb = VK_NULL_HANDLE;
    if (VkResult r = vkCreateFramebuffer(device_, &fi, nullptr, &fb); r != VK_SUCCESS) {
      return vk_failure("vkCreateFramebuffer (swapchain)", r);
    }
    framebuffers_.push_back(fb);
  }
  return {};
}

void Swapchain::destroy_image_objects() {
  for (VkFramebuffer fb : framebuffers_) {
    vkDestroyFramebuffer(device_, fb, nullptr);
  }
  for (VkImageView view : views_) {
    vkDestroyImageView(device_, view, nullptr);
  }
  for (VkSemaphore s : rendered_) {
    vkDestroySemaphore(device_, s, nullptr);
  }
  framebuffers_.clear();
  views_.clear();
  rendered_.clear();
  images_.clear();
}

void Swapchain::destroy() {
  if (device_ == VK_NULL_HANDLE) {
    return;
  }
  destroy_image_objects();
  if (swapchain_ != VK_NULL_HANDLE) {
    vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
  }
}

Swapchain::~Swapchain() {
  destroy();
}

} // namespace snell::viewer
