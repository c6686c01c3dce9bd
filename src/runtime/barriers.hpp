// Internal: synchronization2 image barriers and mip generation shared by all image types.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace snell::detail {

/// One image memory barrier (synchronization2) over a subresource range.
struct ImageBarrier {
  VkImage image = VK_NULL_HANDLE;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  std::uint32_t base_mip = 0, mip_count = VK_REMAINING_MIP_LEVELS;
  std::uint32_t base_layer = 0, layer_count = VK_REMAINING_ARRAY_LAYERS;
  VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED, new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 src_stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
  VkPipelineStageFlags2 dst_stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
};

/// Records the barriers with one vkCmdPipelineBarrier2.
void barrier(VkCommandBuffer cmd, const ImageBarrier* barriers, std::uint32_t count);
inline void barrier(VkCommandBuffer cmd, const ImageBarrier& b) {
  barrier(cmd, &b, 1);
}

/// Stages/accesses of every later reader of a finished target (shaders, copies, blits).
inline constexpr VkPipelineStageFlags2 kReadStages =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_TRANSFER_BIT;
inline constexpr VkAccessFlags2 kReadAccess =
    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT;

/// `area` clamped to `extent`; an empty `area` (0 x 0) is the whole extent. Never empty: an area
/// entirely outside gives a 1 x 1 area at the nearest corner.
VkRect2D clamp_area(VkRect2D area, VkExtent2D extent);

/// vkCmdBeginRendering on one colour view (+ optional depth view) over `area` of `extent`
/// (clamp_area: default the whole extent), with a standard viewport over the whole extent and
/// the scissor set to the area. `clear` = nullptr loads the colour instead of clearing it;
/// depth is cleared to `clear_depth` (loaded when `load_depth`) and stored when `store_depth`.
void begin_rendering(VkCommandBuffer cmd, VkImageView color, VkImageView depth, VkExtent2D extent,
                     std::uint32_t view_mask, const float* clear, float clear_depth,
                     bool store_depth, bool load_depth = false, VkRect2D area = {});

/// Puts a fresh image (layout UNDEFINED) into the state of a target that is samplable before its
/// first pass: colour (`mips` levels x `layers` layers) cleared to transparent black and, when
/// `depth` is not null, depth (level 0, `layers` layers) cleared to 1 (far); both end in
/// SHADER_READ_ONLY_OPTIMAL, visible to kReadStages.
void clear_to_shader_read(VkCommandBuffer cmd, VkImage color, std::uint32_t mips,
                          std::uint32_t layers, VkImage depth);

/// One vkCmdBlitImage2 of colour from `src` (level `src_level`, TRANSFER_SRC_OPTIMAL) to `dst`
/// (level `dst_level`, TRANSFER_DST_OPTIMAL) over `layers` layers: the box `src_min..src_max`
/// (pixels, exclusive max) onto `dst_min..dst_max`.
void blit_color(VkCommandBuffer cmd, VkImage src, std::uint32_t src_level, VkOffset2D src_min,
                VkOffset2D src_max, VkImage dst, std::uint32_t dst_level, VkOffset2D dst_min,
                VkOffset2D dst_max, std::uint32_t layers, VkFilter filter);

/// Generates mip levels 1..mips-1 of `layers` layers by linear blits from level 0.
/// Expects level 0 in `level0_layout` after writes in `src_stage`/`src_access`; leaves every
/// level in SHADER_READ_ONLY_OPTIMAL, visible to kReadStages.
void generate_mips(VkCommandBuffer cmd, VkImage image, std::uint32_t width, std::uint32_t height,
                   std::uint32_t mips, std::uint32_t layers, VkImageLayout level0_layout,
                   VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access);

} // namespace snell::detail
