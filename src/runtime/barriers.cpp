#include "barriers.hpp"

#include "vk_util.hpp"

#include <algorithm>
#include <vector>

namespace snell::detail {

void barrier(VkCommandBuffer cmd, const ImageBarrier* barriers, std::uint32_t count) {
  std::vector<VkImageMemoryBarrier2> vk(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const ImageBarrier& b = barriers[i];
    VkImageMemoryBarrier2& v = vk[i];
    v = vk_init<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
    v.srcStageMask = b.src_stage;
    v.srcAccessMask = b.src_access;
    v.dstStageMask = b.dst_stage;
    v.dstAccessMask = b.dst_access;
    v.oldLayout = b.old_layout;
    v.newLayout = b.new_layout;
    v.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    v.image = b.image;
    v.subresourceRange = {b.aspect, b.base_mip, b.mip_count, b.base_layer, b.layer_count};
  }
  VkDependencyInfo dep = vk_init<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.imageMemoryBarrierCount = count;
  dep.pImageMemoryBarriers = vk.data();
  vkCmdPipelineBarrier2(cmd, &dep);
}

void clear_to_shader_read(VkCommandBuffer cmd, VkImage color, std::uint32_t mips,
                          std::uint32_t layers, VkImage depth) {
  ImageBarrier to_dst[2] = {
      {color, VK_IMAGE_ASPECT_COLOR_BIT, 0, mips, 0, layers, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
      {depth, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
  };
  const std::uint32_t count = depth != VK_NULL_HANDLE ? 2 : 1;
  barrier(cmd, to_dst, count);
  const VkClearColorValue black{{0.0f, 0.0f, 0.0f, 0.0f}};
  const VkImageSubresourceRange colors{VK_IMAGE_ASPECT_COLOR_BIT, 0, mips, 0, layers};
  vkCmdClearColorImage(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &colors);
  if (depth != VK_NULL_HANDLE) {
    const VkClearDepthStencilValue far{1.0f, 0};
    const VkImageSubresourceRange depths{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
    vkCmdClearDepthStencilImage(cmd, depth, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1, &depths);
  }
  ImageBarrier to_read[2] = {to_dst[0], to_dst[1]};
  for (ImageBarrier& b : to_read) {
    b.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    b.src_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    b.src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    b.dst_stage = kReadStages;
    b.dst_access = kReadAccess;
  }
  barrier(cmd, to_read, count);
}

VkRect2D clamp_area(VkRect2D area, VkExtent2D extent) {
  if (area.extent.width == 0 || area.extent.height == 0) {
    return {{0, 0}, extent};
  }
  const auto clamp = [](std::int32_t v, std::uint32_t hi) {
    return static_cast<std::uint32_t>(std::clamp<std::int64_t>(v, 0, hi));
  };
  const std::uint32_t x0 = clamp(area.offset.x, extent.width);
  const std::uint32_t y0 = clamp(area.offset.y, extent.height);
  const std::uint32_t x1 = static_cast<std::uint32_t>(
      std::clamp<std::int64_t>(std::int64_t{area.offset.x} + area.extent.width, x0, extent.width));
  const std::uint32_t y1 = static_cast<std::uint32_t>(std::clamp<std::int64_t>(
      std::int64_t{area.offset.y} + area.extent.height, y0, extent.height));
  if (x1 == x0 || y1 == y0) {
    // Nothing of the area is inside: keep a 1x1 area (an empty one is invalid).
    return {{static_cast<std::int32_t>(std::min(x0, extent.width - 1)),
             static_cast<std::int32_t>(std::min(y0, extent.height - 1))},
            {1, 1}};
  }
  return {{static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)}, {x1 - x0, y1 - y0}};
}

void begin_rendering(VkCommandBuffer cmd, VkImageView color_view, VkImageView depth_view,
                     VkExtent2D extent, std::uint32_t view_mask, const float* clear,
                     float clear_depth, bool store_depth, bool load_depth, VkRect2D area) {
  auto color = vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  color.imageView = color_view;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = clear != nullptr ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  if (clear != nullptr) {
    color.clearValue.color = {{clear[0], clear[1], clear[2], clear[3]}};
  }
  auto depth = vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  depth.imageView = depth_view;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = load_depth ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = store_depth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {clear_depth, 0};
  auto ri = vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  // Loads, clears and stores touch only the render area: a pass that keeps a sub-rectangle
  // (its scissor) leaves the rest of the image as it was and does not pay to clear it.
  ri.renderArea = clamp_area(area, extent);
  ri.layerCount = 1;
  ri.viewMask = view_mask;
  ri.colorAttachmentCount = 1;
  ri.pColorAttachments = &color;
  ri.pDepthAttachment = depth_view != VK_NULL_HANDLE ? &depth : nullptr;
  vkCmdBeginRendering(cmd, &ri);
  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &ri.renderArea);
}

void blit_color(VkCommandBuffer cmd, VkImage src, std::uint32_t src_level, VkOffset2D src_min,
                VkOffset2D src_max, VkImage dst, std::uint32_t dst_level, VkOffset2D dst_min,
                VkOffset2D dst_max, std::uint32_t layers, VkFilter filter) {
  VkImageBlit2 region = vk_init<VkImageBlit2>(VK_STRUCTURE_TYPE_IMAGE_BLIT_2);
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, src_level, 0, layers};
  region.srcOffsets[0] = {src_min.x, src_min.y, 0};
  region.srcOffsets[1] = {src_max.x, src_max.y, 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, dst_level, 0, layers};
  region.dstOffsets[0] = {dst_min.x, dst_min.y, 0};
  region.dstOffsets[1] = {dst_max.x, dst_max.y, 1};
  VkBlitImageInfo2 blit = vk_init<VkBlitImageInfo2>(VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2);
  blit.srcImage = src;
  blit.srcImageLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  blit.dstImage = dst;
  blit.dstImageLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  blit.regionCount = 1;
  blit.pRegions = &region;
  blit.filter = filter;
  vkCmdBlitImage2(cmd, &blit);
}

void generate_mips(VkCommandBuffer cmd, VkImage image, std::uint32_t width, std::uint32_t height,
                   std::uint32_t mips, std::uint32_t layers, VkImageLayout level0_layout,
                   VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access) {
  // Level 0 becomes a blit source; the other levels are discarded and become blit targets.
  const ImageBarrier start[] = {
      {image, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers, level0_layout,
       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, src_stage, src_access, VK_PIPELINE_STAGE_2_BLIT_BIT,
       VK_ACCESS_2_TRANSFER_READ_BIT},
      {image, VK_IMAGE_ASPECT_COLOR_BIT, 1, mips - 1, 0, layers, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
  };
  barrier(cmd, start, mips > 1 ? 2 : 1);
  std::int32_t w = static_cast<std::int32_t>(width);
  std::int32_t h = static_cast<std::int32_t>(height);
  for (std::uint32_t level = 1; level < mips; ++level) {
    const std::int32_t nw = std::max(1, w / 2);
    const std::int32_t nh = std::max(1, h / 2);
    blit_color(cmd, image, level - 1, {0, 0}, {w, h}, image, level, {0, 0}, {nw, nh}, layers,
               VK_FILTER_LINEAR);
    // The level just written becomes the source of the next one.
    barrier(cmd,
            ImageBarrier{image, VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, layers,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT});
    w = nw;
    h = nh;
  }
  barrier(cmd, ImageBarrier{image, VK_IMAGE_ASPECT_COLOR_BIT, 0, mips, 0, layers,
                            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            kReadStages, kReadAccess});
}

} // namespace snell::detail
