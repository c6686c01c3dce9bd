// SceneSnapshot: one copy of the opaque colour (with mips) and depth per frame.
#include <snell/context.hpp>
#include <snell/snapshot.hpp>
#include <snell/toolkit/vk_check.hpp>

#include "../runtime/barriers.hpp"
#include "../runtime/runtime_internal.hpp"

namespace snell {

using detail::ImageBarrier;

Result<SceneSnapshot> SceneSnapshot::create(const Context& ctx, const SnapshotDesc& desc) {
  if (desc.frames_in_flight < 1 || desc.frames_in_flight > 16) {
    return fail(ErrorCode::invalid_argument,
                "SnapshotDesc::frames_in_flight = " + std::to_string(desc.frames_in_flight) +
                    " is outside [1, 16]");
  }
  SceneSnapshot s;
  s.ctx_ = &ctx;
  s.desc_ = desc;
  s.release_ = DeferredRelease(desc.frames_in_flight);
  return s;
}

namespace {

constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkPipelineStageFlags2 kColorWriters =
    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_TRANSFER_BIT;

/// The ColorFormat whose VkFormat is `format`, or `fallback`.
ColorFormat color_format_of(VkFormat format, ColorFormat fallback) {
  for (const ColorFormat f :
       {ColorFormat::rgba8_unorm, ColorFormat::rgba8_srgb, ColorFormat::rgba16_float}) {
    if (to_vk_format(f) == format) {
      return f;
    }
  }
  return fallback;
}

} // namespace

namespace {

/// Copies `region` of level 0 (same formats; TRANSFER_SRC -> TRANSFER_DST).
void copy_image(VkCommandBuffer cmd, VkImage from, VkImage to, VkImageAspectFlags aspect,
                VkRect2D region) {
  auto copy_region = vk_struct<VkImageCopy2>(VK_STRUCTURE_TYPE_IMAGE_COPY_2);
  copy_region.srcSubresource = {aspect, 0, 0, 1};
  copy_region.dstSubresource = copy_region.srcSubresource;
  copy_region.srcOffset = {region.offset.x, region.offset.y, 0};
  copy_region.dstOffset = copy_region.srcOffset;
  copy_region.extent = {region.extent.width, region.extent.height, 1};
  auto copy = vk_struct<VkCopyImageInfo2>(VK_STRUCTURE_TYPE_COPY_IMAGE_INFO_2);
  copy.srcImage = from;
  copy.srcImageLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  copy.dstImage = to;
  copy.dstImageLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  copy.regionCount = 1;
  copy.pRegions = &copy_region;
  vkCmdCopyImage2(cmd, &copy);
}

} // namespace

Result<void> SceneSnapshot::record(VkCommandBuffer cmd, const SnapshotSource& src,
                                   std::uint64_t frame_index) {
  if (ctx_ == nullptr) {
    return fail(ErrorCode::invalid_argument, "scene snapshot: not created (SceneSnapshot::create)");
  }
  if (src.color == VK_NULL_HANDLE) {
    return fail(ErrorCode::invalid_argument, "scene snapshot: SnapshotSource::color is null");
  }
  if (src.extent.width == 0 || src.extent.height == 0) {
    return fail(ErrorCode::invalid_argument, "scene snapshot: SnapshotSource::extent is " +
                                                 std::to_string(src.extent.width) + "x" +
                                                 std::to_string(src.extent.height));
  }
  release_.collect(frame_index);
  // The source's own format when it is one of ColorFormat's: a copy instead of a conversion.
  const ColorFormat format = color_format_of(src.color_format, desc_.color);
  if (!target_ || target_.width() != src.extent.width || target_.height() != src.extent.height ||
      target_.color_format() != format) {
    RenderTargetDesc rd;
    rd.width = src.extent.width;
    rd.height = src.extent.height;
    rd.color = format;
    rd.depth = true;
    rd.mips = desc_.mips;
    rd.debug_name = "scene snapshot";
    // Cleared inside `cmd`: record() may itself run inside Context::submit_and_wait.
    auto t = create_render_target(*ctx_, rd, cmd);
    if (!t) {
      return t.error();
    }
    if (target_) {
      release_.retire(frame_index, std::move(target_));
    }
    target_ = std::move(*t);
  }
  const bool depth = src.depth != VK_NULL_HANDLE;
  const VkRect2D region = detail::clamp_area(src.region, src.extent);
  const bool whole =
      region.extent.width == src.extent.width && region.extent.height == src.extent.height;
  // A partial copy keeps the rest of the older contents: the copies leave their samplable
  // layout instead of UNDEFINED.
  const VkImageLayout dst_old =
      whole ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  // Sources to TRANSFER_SRC after the opaque phase's writes; the copies' level 0 and depth to
  // TRANSFER_DST after the previous frame's reads.
  const ImageBarrier before[4] = {
      {src.color, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1, src.color_layout,
       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kColorWriters | kTransfer,
       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT, kTransfer,
       VK_ACCESS_2_TRANSFER_READ_BIT},
      {target_.color_image(), VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1, dst_old,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE, kTransfer,
       VK_ACCESS_2_TRANSFER_WRITE_BIT},
      {target_.depth_image(), VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1, dst_old,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE, kTransfer,
       VK_ACCESS_2_TRANSFER_WRITE_BIT},
      {src.depth, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1, src.depth_layout,
       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kDepthStages | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT},
  };
  detail::barrier(cmd, before, depth ? 4 : 2);
  // Colour: a plain copy in the source's format, else a same-size blit that converts.
  if (target_.vk_color_format() == src.color_format) {
    copy_image(cmd, src.color, target_.color_image(), VK_IMAGE_ASPECT_COLOR_BIT, region);
  } else {
    // A same-size blit that converts the format (nearest: no filtering).
    const VkOffset2D lo = region.offset;
    const VkOffset2D hi{lo.x + static_cast<std::int32_t>(region.extent.width),
                        lo.y + static_cast<std::int32_t>(region.extent.height)};
    detail::blit_color(cmd, src.color, 0, lo, hi, target_.color_image(), 0, lo, hi, 1,
                       VK_FILTER_NEAREST);
  }
  if (depth) {
    copy_image(cmd, src.depth, target_.depth_image(), VK_IMAGE_ASPECT_DEPTH_BIT, region);
  }
  finish(cmd, src);
  view_proj_ = src.view_proj;
  ++copies_;
  return {};
}

VkRect2D union_region(VkRect2D a, VkRect2D b) {
  const auto everything = [](const VkRect2D& r) {
    return r.extent.width == 0 || r.extent.height == 0;
  };
  if (everything(a) || everything(b)) {
    return {};
  }
  const std::int64_t x0 = std::min(a.offset.x, b.offset.x);
  const std::int64_t y0 = std::min(a.offset.y, b.offset.y);
  const std::int64_t x1 = std::max(std::int64_t{a.offset.x} + a.extent.width,
                                   std::int64_t{b.offset.x} + b.extent.width);
  const std::int64_t y1 = std::max(std::int64_t{a.offset.y} + a.extent.height,
                                   std::int64_t{b.offset.y} + b.extent.height);
  return {{static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)},
          {static_cast<std::uint32_t>(x1 - x0), static_cast<std::uint32_t>(y1 - y0)}};
}

void SceneSnapshot::finish(VkCommandBuffer cmd, const SnapshotSource& src) const {
  const bool depth = src.depth != VK_NULL_HANDLE;
  // Sources back to their layouts for the surfaces phase; the depth copy to SHADER_READ_ONLY.
  const ImageBarrier after[3] = {
      {src.color, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
       src.color_layout, kTransfer, VK_ACCESS_2_NONE, kColorWriters | detail::kReadStages,
       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT |
           detail::kReadAccess},
      {target_.depth_image(), VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1,
       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kTransfer,
       VK_ACCESS_2_TRANSFER_WRITE_BIT, detail::kReadStages, detail::kReadAccess},
      {src.depth, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
       src.depth_layout, kTransfer, VK_ACCESS_2_NONE, kDepthStages | detail::kReadStages,
       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | detail::kReadAccess},
  };
  detail::barrier(cmd, after, depth ? 3 : 1);
  if (src.mips && target_.mip_levels() > 1) {
    detail::generate_mips(cmd, target_.color_image(), target_.width(), target_.height(),
                          target_.mip_levels(), 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kTransfer,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
  } else {
    // Level 0 only; the other levels keep SHADER_READ_ONLY_OPTIMAL (and older contents).
    detail::barrier(cmd, ImageBarrier{target_.color_image(), VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1,
                                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kTransfer,
                                      VK_ACCESS_2_TRANSFER_WRITE_BIT, detail::kReadStages,
                                      detail::kReadAccess});
  }
}

std::vector<DebugTarget> SceneSnapshot::debug_targets() const {
  std::vector<DebugTarget> out;
  if (!target_) {
    return out;
  }
  DebugTarget c;
  c.name = "snapshot.color";
  c.view = target_.color_view();
  c.image = target_.color_image();
  c.width = target_.width();
  c.height = target_.height();
  c.format = target_.vk_color_format();
  out.push_back(c);
  if (target_.mip_levels() > 2) {
    DebugTarget m = c;
    m.name = "snapshot.color_mip2";
    m.kind = DebugKind::mip_level;
    m.mip = 2;
    m.width = std::max(1u, c.width >> 2);
    m.height = std::max(1u, c.height >> 2);
    out.push_back(m);
  }
  DebugTarget d = c;
  d.name = "snapshot.depth";
  d.kind = DebugKind::depth;
  d.view = target_.depth_view();
  d.image = target_.depth_image();
  d.format = VK_FORMAT_D32_SFLOAT;
  out.push_back(d);
  return out;
}

} // namespace snell
