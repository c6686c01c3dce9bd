// Internal: draws debug thumbnails of intermediate targets into the corners of the output
// (seed 004's debug window, seed 001's reflection/refraction thumbnails).
#pragma once

#include <snell/frame.hpp>

#include "context_impl.hpp"

namespace snell::detail {

class DebugOverlay {
public:
  static Result<DebugOverlay> create(const ContextState& ctx, VkFormat color_format);
  DebugOverlay() = default;
  DebugOverlay(DebugOverlay&& o) noexcept;
  DebugOverlay& operator=(DebugOverlay&& o) noexcept;
  DebugOverlay(const DebugOverlay&) = delete;
  DebugOverlay& operator=(const DebugOverlay&) = delete;
  ~DebugOverlay();

  /// Inside an overlay rendering: every target as a thumbnail. Up to 4 go into the corners
  /// (a quarter of the output each, clockwise from the top-left); more are laid out in a grid
  /// of ceil(sqrt(n)) columns over the whole output, in order. At most kMaxThumbnails (64).
  void draw(VkCommandBuffer cmd, Span<const DebugTarget> targets, std::uint32_t width,
            std::uint32_t height);

  static constexpr std::uint32_t kMaxThumbnails = 64;

private:
  void swap(DebugOverlay& o) noexcept;
  const ContextState* ctx_ = nullptr;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;       ///< Linear, for colour.
  VkSampler depth_sampler_ = VK_NULL_HANDLE; ///< Nearest: depth formats need not filter.
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet sets_[kMaxThumbnails] = {};
};

} // namespace snell::detail
