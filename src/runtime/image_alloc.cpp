#include "image_alloc.hpp"

#include <snell/images.hpp>

#include "vk_util.hpp"

namespace snell::detail {

Result<void> create_image(const ContextState& ctx, const VkImageCreateInfo& ci, VkImage& image,
                          VkDeviceMemory& memory, std::string_view name) {
  SNELL_VK_TRY(vkCreateImage(ctx.device, &ci, nullptr, &image), name);
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(ctx.device, image, &req);
  auto type = ctx.find_memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!type) {
    type = ctx.find_memory_type(req.memoryTypeBits, 0);
  }
  if (!type) {
    vkDestroyImage(ctx.device, image, nullptr);
    image = VK_NULL_HANDLE;
    return fail(ErrorCode::out_of_memory, std::string(name) + ": " + type.error().message);
  }
  VkMemoryAllocateInfo ai = vk_init<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = *type;
  VkResult r = vkAllocateMemory(ctx.device, &ai, nullptr, &memory);
  if (r == VK_SUCCESS) {
    r = vkBindImageMemory(ctx.device, image, memory, 0);
  }
  if (r != VK_SUCCESS) {
    destroy(&ctx, image, memory);
    return vk_error("vkAllocateMemory/vkBindImageMemory", r, name);
  }
  return {};
}

Result<VkImageView> create_view(const ContextState& ctx, VkImage image, VkImageViewType type,
                                VkFormat format, VkImageAspectFlags aspect, std::uint32_t base_mip,
                                std::uint32_t mip_count, std::uint32_t base_layer,
                                std::uint32_t layer_count, std::string_view name) {
  VkImageViewCreateInfo ci =
      vk_init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  ci.image = image;
  ci.viewType = type;
  ci.format = format;
  ci.subresourceRange = {aspect, base_mip, mip_count, base_layer, layer_count};
  VkImageView view = VK_NULL_HANDLE;
  SNELL_VK_TRY(vkCreateImageView(ctx.device, &ci, nullptr, &view), name);
  return view;
}

Result<void> check_extent(const ContextState& ctx, std::string_view what, std::uint32_t width,
                          std::uint32_t height) {
  const std::uint32_t limit = std::min(kMaxImageDimension, ctx.limits.maxImageDimension2D);
  if (width == 0 || height == 0 || width > limit || height > limit) {
    return fail(ErrorCode::invalid_argument, std::string(what) + ": size " + std::to_string(width) +
                                                 "x" + std::to_string(height) +
                                                 " is out of range (each side 1.." +
                                                 std::to_string(limit) + ")");
  }
  return {};
}

void destroy(const ContextState* ctx, VkImage& image, VkDeviceMemory& memory) {
  if (ctx == nullptr) {
    return;
  }
  if (image != VK_NULL_HANDLE) {
    vkDestroyImage(ctx->device, image, nullptr);
  }
  if (memory != VK_NULL_HANDLE) {
    vkFreeMemory(ctx->device, memory, nullptr);
  }
  image = VK_NULL_HANDLE;
  memory = VK_NULL_HANDLE;
}

void destroy(const ContextState* ctx, VkImageView& view) {
  if (ctx != nullptr && view != VK_NULL_HANDLE) {
    vkDestroyImageView(ctx->device, view, nullptr);
  }
  view = VK_NULL_HANDLE;
}

} // namespace snell::detail
