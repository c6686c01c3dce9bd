// Internal: creating VkImages with dedicated memory, and views.
#pragma once

#include "context_impl.hpp"

#include <string>
#include <string_view>

namespace snell::detail {

/// Creates `ci`'s image with its own device-local memory. On error nothing is left allocated.
Result<void> create_image(const ContextState& ctx, const VkImageCreateInfo& ci, VkImage& image,
                          VkDeviceMemory& memory, std::string_view name);

/// Creates a view of `image`.
Result<VkImageView> create_view(const ContextState& ctx, VkImage image, VkImageViewType type,
                                VkFormat format, VkImageAspectFlags aspect, std::uint32_t base_mip,
                                std::uint32_t mip_count, std::uint32_t base_layer,
                                std::uint32_t layer_count, std::string_view name);

/// Checks a width x height against 1..kMaxImageDimension and the device limit; names `what`.
Result<void> check_extent(const ContextState& ctx, std::string_view what, std::uint32_t width,
                          std::uint32_t height);

/// Destroys the non-null handles (helper for resets).
void destroy(const ContextState* ctx, VkImage& image, VkDeviceMemory& memory);
void destroy(const ContextState* ctx, VkImageView& view);

} // namespace snell::detail
