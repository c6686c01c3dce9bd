// Render targets: colour (+ depth) images for dynamic rendering, sampled afterwards.
#include <snell/images.hpp>

#include "barriers.hpp"
#include "image_alloc.hpp"
#include "runtime_internal.hpp"
#include "vk_util.hpp"

#include <algorithm>
#include <utility>

namespace snell {

using detail::vk_init;

using detail::ImageBarrier;

std::uint32_t full_mip_count(std::uint32_t width, std::uint32_t height) {
  std::uint32_t n = 1;
  for (std::uint32_t s = std::max(width, height); s > 1; s >>= 1) {
    ++n;
  }
  return n;
}

VkFormat to_vk_format(ColorFormat format) {
  switch (format) {
  case ColorFormat::rgba8_unorm:
    return VK_FORMAT_R8G8B8A8_UNORM;
  case ColorFormat::rgba8_srgb:
    return VK_FORMAT_R8G8B8A8_SRGB;
  case ColorFormat::rgba16_float:
    return VK_FORMAT_R16G16B16A16_SFLOAT;
  }
  return VK_FORMAT_R8G8B8A8_UNORM;
}

Result<RenderTarget> RenderTarget::create(const Context& context, const RenderTargetDesc& desc) {
  return create_render_target(context, desc, VK_NULL_HANDLE);
}

Result<RenderTarget> create_render_target(const Context& context, const RenderTargetDesc& desc,
                                          VkCommandBuffer clear_into) {
  const ContextState& ctx = *context_state(context);
  const std::string name = desc.debug_name != nullptr ? desc.debug_name : "render target";
  if (auto r = detail::check_extent(ctx, name + " (RenderTargetDesc width x height)", desc.width,
                                    desc.height);
      !r) {
    return r.error();
  }
  RenderTarget t;
  t.ctx_ = &ctx;
  t.width_ = desc.width;
  t.height_ = desc.height;
  t.format_ = desc.color;
  t.mips_ = desc.mips ? full_mip_count(desc.width, desc.height) : 1;
  VkImageCreateInfo ci = vk_init<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  ci.imageType = VK_IMAGE_TYPE_2D;
  ci.format = to_vk_format(desc.color);
  ci.extent = {desc.width, desc.height, 1};
  ci.mipLevels = t.mips_;
  ci.arrayLayers = 1;
  ci.samples = VK_SAMPLE_COUNT_1_BIT;
  ci.tiling = VK_IMAGE_TILING_OPTIMAL;
  ci.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
             VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (auto r = detail::create_image(ctx, ci, t.color_, t.color_memory_, name + " colour"); !r) {
    return r.error();
  }
  auto view = detail::create_view(ctx, t.color_, VK_IMAGE_VIEW_TYPE_2D, ci.format,
                                  VK_IMAGE_ASPECT_COLOR_BIT, 0, t.mips_, 0, 1, name);
  if (!view) {
    return view.error();
  }
  t.color_view_ = *view;
  view = detail::create_view(ctx, t.color_, VK_IMAGE_VIEW_TYPE_2D, ci.format,
                             VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1, name);
  if (!view) {
    return view.error();
  }
  t.color_level0_view_ = *view;
  if (desc.depth) {
    ci.format = VK_FORMAT_D32_SFLOAT;
    ci.mipLevels = 1;
    ci.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
               VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (auto r = detail::create_image(ctx, ci, t.depth_, t.depth_memory_, name + " depth"); !r) {
      return r.error();
    }
    view = detail::create_view(ctx, t.depth_, VK_IMAGE_VIEW_TYPE_2D, ci.format,
                               VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1, name);
    if (!view) {
      return view.error();
    }
    t.depth_view_ = *view;
  }
  // Toolkit targets are samplable from creation on: a surface or the debug overlay may read a
  // target whose pass was skipped this frame (a camera behind a mirror), which must not be an
  // image in layout UNDEFINED. Cleared to transparent black and depth 1 (far).
  if (clear_into != VK_NULL_HANDLE) {
    detail::clear_to_shader_read(clear_into, t.color_, t.mips_, 1, t.depth_);
    return t;
  }
  if (auto r = ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        detail::clear_to_shader_read(cmd, t.color_, t.mips_, 1, t.depth_);
      });
      !r) {
    return r.error();
  }
  return t;
}

RenderTarget::RenderTarget(RenderTarget&& other) noexcept {
  swap(other);
}
RenderTarget& RenderTarget::operator=(RenderTarget&& other) noexcept {
  RenderTarget moved(std::move(other));
  swap(moved);
  return *this;
}
RenderTarget::~RenderTarget() {
  reset();
}

void RenderTarget::swap(RenderTarget& o) noexcept {
  std::swap(ctx_, o.ctx_);
  std::swap(width_, o.width_);
  std::swap(height_, o.height_);
  std::swap(mips_, o.mips_);
  std::swap(format_, o.format_);
  std::swap(color_, o.color_);
  std::swap(depth_, o.depth_);
  std::swap(color_memory_, o.color_memory_);
  std::swap(depth_memory_, o.depth_memory_);
  std::swap(color_view_, o.color_view_);
  std::swap(color_level0_view_, o.color_level0_view_);
  std::swap(depth_view_, o.depth_view_);
}

void RenderTarget::reset() {
  detail::destroy(ctx_, color_view_);
  detail::destroy(ctx_, color_level0_view_);
  detail::destroy(ctx_, depth_view_);
  detail::destroy(ctx_, color_, color_memory_);
  detail::destroy(ctx_, depth_, depth_memory_);
  ctx_ = nullptr;
}

void RenderTarget::begin_rendering(VkCommandBuffer cmd, const float clear[4], float clear_depth,
                                   VkRect2D area) const {
  // The whole target is cleared, so its old layout is UNDEFINED (contents discarded). With an
  // area, what lies outside keeps its contents: the old layout is the samplable one every
  // target is in between passes. Either way the barrier orders this pass's writes after earlier
  // reads of the previous contents (write-after-read).
  const bool whole = area.extent.width == 0 || area.extent.height == 0;
  const VkImageLayout old_layout =
      whole ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  ImageBarrier barriers[2] = {
      {color_, VK_IMAGE_ASPECT_COLOR_BIT, 0, mips_, 0, 1, old_layout,
       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT},
      {depth_, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1, old_layout,
       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT},
  };
  detail::barrier(cmd, barriers, depth_ != VK_NULL_HANDLE ? 2 : 1);

  detail::begin_rendering(cmd, color_level0_view_, depth_view_, {width_, height_}, 0, clear,
                          clear_depth, true, false, area);
}

void RenderTarget::continue_rendering(VkCommandBuffer cmd) const {
  ImageBarrier barriers[2] = {
      {color_, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT},
      {depth_, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT},
  };
  detail::barrier(cmd, barriers, depth_ != VK_NULL_HANDLE ? 2 : 1);
  detail::begin_rendering(cmd, color_level0_view_, depth_view_, {width_, height_}, 0, nullptr, 1.0f,
                          true, true);
}

void RenderTarget::begin_overlay(VkCommandBuffer cmd) const {
  detail::barrier(
      cmd,
      ImageBarrier{color_, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
                   VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT});
  detail::begin_rendering(cmd, color_level0_view_, VK_NULL_HANDLE, {width_, height_}, 0, nullptr,
                          1.0f, false);
}

void RenderTarget::end_overlay(VkCommandBuffer cmd) const {
  finish_color(cmd);
}

void RenderTarget::finish_color(VkCommandBuffer cmd) const {
  vkCmdEndRendering(cmd);
  if (mips_ > 1) {
    detail::generate_mips(
        cmd, color_, width_, height_, mips_, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  } else {
    detail::barrier(cmd, ImageBarrier{color_, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1,
                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, detail::kReadStages,
                                      detail::kReadAccess});
  }
}

void RenderTarget::end_rendering(VkCommandBuffer cmd) const {
  finish_color(cmd);
  if (depth_ != VK_NULL_HANDLE) {
    detail::barrier(cmd, ImageBarrier{depth_, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1,
                                      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                      VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                      detail::kReadStages, detail::kReadAccess});
  }
}

} // namespace snell
