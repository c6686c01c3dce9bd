// Cube targets: six-layer colour + depth for environment capture, per-face and multiview.
#include <snell/images.hpp>

#include "barriers.hpp"
#include "image_alloc.hpp"
#include "vk_util.hpp"

#include <utility>

namespace snell {

using detail::vk_init;

using detail::ImageBarrier;

Result<CubeTarget> CubeTarget::create(const Context& context, const CubeTargetDesc& desc) {
  const ContextState& ctx = *context_state(context);
  const std::string name = desc.debug_name != nullptr ? desc.debug_name : "cube target";
  if (auto r = detail::check_extent(ctx, name + " (CubeTargetDesc::size)", desc.size, desc.size);
      !r) {
    return r.error();
  }
  if (desc.storage) {
    // A storage image needs a format with STORAGE_IMAGE support for optimal tiling (rgba8_srgb
    // has none on most devices): refused here rather than by vkCreateImage.
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(ctx.physical_device, to_vk_format(desc.color), &props);
    if ((props.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) == 0) {
      return fail(ErrorCode::unsupported,
                  name + ": CubeTargetDesc::storage needs a colour format the device can store "
                         "to (rgba8_unorm or rgba16_float); this one has no storage support");
    }
  }
  CubeTarget t;
  t.ctx_ = &ctx;
  t.storage_ = desc.storage;
  t.size_ = desc.size;
  t.format_ = desc.color;
  t.mips_ = desc.mips ? full_mip_count(desc.size, desc.size) : 1;
  VkImageCreateInfo ci = vk_init<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  ci.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  ci.imageType = VK_IMAGE_TYPE_2D;
  ci.format = to_vk_format(desc.color);
  ci.extent = {desc.size, desc.size, 1};
  ci.mipLevels = t.mips_;
  ci.arrayLayers = 6;
  ci.samples = VK_SAMPLE_COUNT_1_BIT;
  ci.tiling = VK_IMAGE_TILING_OPTIMAL;
  ci.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
             VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
             (desc.storage ? VkImageUsageFlags{VK_IMAGE_USAGE_STORAGE_BIT} : VkImageUsageFlags{0});
  if (auto r = detail::create_image(ctx, ci, t.color_, t.color_memory_, name + " colour"); !r) {
    return r.error();
  }
  const VkFormat color_format = ci.format;
  ci.flags = 0;
  ci.format = VK_FORMAT_D32_SFLOAT;
  ci.mipLevels = 1;
  ci.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (auto r = detail::create_image(ctx, ci, t.depth_, t.depth_memory_, name + " depth"); !r) {
    return r.error();
  }
  auto view = [&](VkImage image, VkImageViewType type, VkFormat format, VkImageAspectFlags aspect,
                  std::uint32_t mips, std::uint32_t base_layer, std::uint32_t layers,
                  VkImageView& out) -> Result<void> {
    auto v =
        detail::create_view(ctx, image, type, format, aspect, 0, mips, base_layer, layers, name);
    if (!v) {
      return v.error();
    }
    out = *v;
    return {};
  };
  Result<void> r = view(t.color_, VK_IMAGE_VIEW_TYPE_CUBE, color_format, VK_IMAGE_ASPECT_COLOR_BIT,
                        t.mips_, 0, 6, t.cube_view_);
  if (r) {
    r = view(t.color_, VK_IMAGE_VIEW_TYPE_2D_ARRAY, color_format, VK_IMAGE_ASPECT_COLOR_BIT, 1, 0,
             6, t.array_view_);
  }
  if (r) {
    r = view(t.depth_, VK_IMAGE_VIEW_TYPE_2D_ARRAY, VK_FORMAT_D32_SFLOAT, VK_IMAGE_ASPECT_DEPTH_BIT,
             1, 0, 6, t.depth_array_view_);
  }
  for (std::uint32_t f = 0; f < 6 && r; ++f) {
    r = view(t.color_, VK_IMAGE_VIEW_TYPE_2D, color_format, VK_IMAGE_ASPECT_COLOR_BIT, 1, f, 1,
             t.face_views_[f]);
    if (r) {
      r = view(t.depth_, VK_IMAGE_VIEW_TYPE_2D, VK_FORMAT_D32_SFLOAT, VK_IMAGE_ASPECT_DEPTH_BIT, 1,
               f, 1, t.depth_face_views_[f]);
    }
  }
  if (!r) {
    return r.error();
  }
  // Samplable from creation on (like every toolkit target): a surface may sample a cube whose
  // capture has not run yet. Cleared to transparent black, SHADER_READ_ONLY_OPTIMAL.
  r = ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    detail::clear_to_shader_read(cmd, t.color_, t.mips_, 6, VK_NULL_HANDLE);
  });
  if (!r) {
    return r.error();
  }
  return t;
}

CubeTarget::CubeTarget(CubeTarget&& other) noexcept {
  swap(other);
}
CubeTarget& CubeTarget::operator=(CubeTarget&& other) noexcept {
  CubeTarget moved(std::move(other));
  swap(moved);
  return *this;
}
CubeTarget::~CubeTarget() {
  reset();
}

void CubeTarget::swap(CubeTarget& o) noexcept {
  std::swap(ctx_, o.ctx_);
  std::swap(size_, o.size_);
  std::swap(mips_, o.mips_);
  std::swap(format_, o.format_);
  std::swap(storage_, o.storage_);
  std::swap(color_, o.color_);
  std::swap(depth_, o.depth_);
  std::swap(color_memory_, o.color_memory_);
  std::swap(depth_memory_, o.depth_memory_);
  std::swap(cube_view_, o.cube_view_);
  std::swap(array_view_, o.array_view_);
  std::swap(depth_array_view_, o.depth_array_view_);
  std::swap(face_views_, o.face_views_);
  std::swap(depth_face_views_, o.depth_face_views_);
}

void CubeTarget::reset() {
  detail::destroy(ctx_, cube_view_);
  detail::destroy(ctx_, array_view_);
  detail::destroy(ctx_, depth_array_view_);
  for (int f = 0; f < 6; ++f) {
    detail::destroy(ctx_, face_views_[f]);
    detail::destroy(ctx_, depth_face_views_[f]);
  }
  detail::destroy(ctx_, color_, color_memory_);
  detail::destroy(ctx_, depth_, depth_memory_);
  ctx_ = nullptr;
}

void CubeTarget::begin_capture(VkCommandBuffer cmd, bool keep_contents) const {
  // Kept contents come from SHADER_READ_ONLY_OPTIMAL, where every capture leaves the cube.
  const VkImageLayout old_color =
      keep_contents ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  const ImageBarrier barriers[2] = {
      {color_, VK_IMAGE_ASPECT_COLOR_BIT, 0, mips_, 0, 6, old_color,
       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, detail::kReadStages, VK_ACCESS_2_NONE,
       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT},
      {depth_, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 6, VK_IMAGE_LAYOUT_UNDEFINED,
       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
       VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT},
  };
  detail::barrier(cmd, barriers, 2);
}

void CubeTarget::begin_face(VkCommandBuffer cmd, std::uint32_t face, const float clear[4]) const {
  detail::begin_rendering(cmd, face_views_[face % 6], depth_face_views_[face % 6], {size_, size_},
                          0, clear, 1.0f, false);
}

void CubeTarget::end_face(VkCommandBuffer cmd) const {
  vkCmdEndRendering(cmd);
}

void CubeTarget::begin_multiview(VkCommandBuffer cmd, const float clear[4]) const {
  detail::begin_rendering(cmd, array_view_, depth_array_view_, {size_, size_}, 0x3Fu, clear, 1.0f,
                          false);
}

void CubeTarget::end_multiview(VkCommandBuffer cmd) const {
  vkCmdEndRendering(cmd);
}

void CubeTarget::end_capture(VkCommandBuffer cmd, bool mips) const {
  if (mips_ > 1 && mips) {
    detail::generate_mips(
        cmd, color_, size_, size_, mips_, 6, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    return;
  }
  detail::barrier(cmd, ImageBarrier{color_, VK_IMAGE_ASPECT_COLOR_BIT, 0, mips_, 0, 6,
                                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, detail::kReadStages,
                                    detail::kReadAccess});
}

} // namespace snell
