// ScaledTarget: a render target that follows the output extent at a scale.
#include <snell/toolkit/scaled_target.hpp>

#include <algorithm>
#include <cmath>

namespace snell {

VkExtent2D scaled_extent(VkExtent2D output, float scale) {
  const auto scaled = [&](std::uint32_t v) {
    return std::max(1u, static_cast<std::uint32_t>(static_cast<float>(v) * scale + 0.5f));
  };
  return {scaled(output.width), scaled(output.height)};
}

namespace {

/// Levels of a full mip chain of `e`.
std::uint32_t full_mip_levels(VkExtent2D e) {
  std::uint32_t levels = 1;
  for (std::uint32_t side = std::max(e.width, e.height); side > 1; side >>= 1) {
    ++levels;
  }
  return levels;
}

} // namespace

Result<bool> ScaledTarget::fit(const Context& ctx, VkExtent2D output, std::uint64_t frame_index,
                               DeferredRelease& release) {
  const std::string label = desc_.label != nullptr ? desc_.label : "scaled target";
  if (!(desc_.scale > 0.0f && desc_.scale <= 4.0f)) {
    return fail(ErrorCode::invalid_argument,
                label + ": scale " + std::to_string(desc_.scale) + " is outside (0, 4]");
  }
  if (output.width == 0 || output.height == 0) {
    return fail(ErrorCode::invalid_argument, label + ": the output extent is " +
                                                 std::to_string(output.width) + "x" +
                                                 std::to_string(output.height));
  }
  const VkExtent2D e = scaled_extent(output, desc_.scale);
  const bool has_mips = target_ && target_.mip_levels() > 1;
  const bool wants_mips = desc_.mips && full_mip_levels(e) > 1;
  if (target_ && target_.width() == e.width && target_.height() == e.height &&
      has_mips == wants_mips) {
    return false;
  }
  RenderTargetDesc rd;
  rd.width = e.width;
  rd.height = e.height;
  rd.color = desc_.color;
  rd.depth = desc_.depth;
  rd.mips = desc_.mips;
  rd.debug_name = desc_.label;
  auto t = RenderTarget::create(ctx, rd);
  if (!t) {
    return t.error();
  }
  if (target_) {
    release.retire(frame_index, std::move(target_));
  }
  target_ = std::move(*t);
  return true;
}

void ScaledTarget::append_debug_targets(std::vector<DebugTarget>& out,
                                        const std::string& name) const {
  if (!target_) {
    return;
  }
  DebugTarget c;
  c.name = name;
  c.kind = DebugKind::color;
  c.view = target_.color_view();
  c.image = target_.color_image();
  c.width = target_.width();
  c.height = target_.height();
  c.format = target_.vk_color_format();
  out.push_back(c);
  if (target_.depth_image() != VK_NULL_HANDLE) {
    DebugTarget d = c;
    d.name = name + "_depth";
    d.kind = DebugKind::depth;
    d.view = target_.depth_view();
    d.image = target_.depth_image();
    d.format = target_.depth_format();
    out.push_back(d);
  }
}

} // namespace snell
