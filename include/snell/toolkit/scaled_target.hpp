// Snell plugin toolkit: a render target that follows the host's output extent at a scale (a
// reflection at half resolution, say). When the output or the scale changes it recreates the
// target and retires the old one past the frames in flight; it never idles the device.
#pragma once

#include <snell/effect.hpp>
#include <snell/images.hpp>
#include <snell/toolkit/deferred_release.hpp>

#include <cstdint>
#include <string>

namespace snell {

/// Parameters of a ScaledTarget.
struct ScaledTargetDesc {
  /// Target size relative to the output, per axis (rounded, at least 1 pixel). (0, 4].
  /// Default 1.
  float scale = 1.0f;
  ColorFormat color = ColorFormat::rgba16_float; ///< Default rgba16_float (HDR).
  bool depth = true;                             ///< A sampled D32 depth image. Default true.
  bool mips = false;                             ///< A full colour mip chain. Default false.
  const char* label = "scaled target";           ///< Names it in errors and debug targets.
};

/// A RenderTarget sized `round(output * scale)`. Like every toolkit target it is samplable
/// (SHADER_READ_ONLY_OPTIMAL, cleared to transparent black and depth 1) from creation on, so a
/// surface may sample it on a frame whose pass was skipped.
class ScaledTarget {
public:
  ScaledTarget() = default;
  explicit ScaledTarget(const ScaledTargetDesc& desc) : desc_(desc) {}

  /// Makes the target match `output` at the current scale: creates it the first time and
  /// recreates it when the size or the mip setting changed, retiring the old one into `release` at
  /// `frame_index`. Returns true when a new image was made (descriptors that point at it must be
  /// updated). Errors: invalid_argument (scale outside (0, 4], an empty output), out_of_memory.
  [[nodiscard]] Result<bool> fit(const Context& ctx, VkExtent2D output, std::uint64_t frame_index,
                                 DeferredRelease& release);
  /// Changes the scale; the next fit() applies it.
  void set_scale(float scale) { desc_.scale = scale; }
  /// Turns the colour mip chain on or off (building it costs a blit chain per pass: an effect
  /// that samples only level 0 this frame turns it off); the next fit() applies it.
  void set_mips(bool mips) { desc_.mips = mips; }
  [[nodiscard]] float scale() const { return desc_.scale; }

  [[nodiscard]] const RenderTarget& target() const { return target_; }
  [[nodiscard]] RenderTarget& target() { return target_; }
  [[nodiscard]] VkExtent2D extent() const { return {target_.width(), target_.height()}; }
  [[nodiscard]] explicit operator bool() const { return static_cast<bool>(target_); }

  /// Debug targets of the colour (kind color) and, with depth, of the depth image, named
  /// `<name>` and `<name>_depth`.
  void append_debug_targets(std::vector<DebugTarget>& out, const std::string& name) const;

private:
  ScaledTargetDesc desc_;
  RenderTarget target_;
};

/// `round(output * scale)` per axis, at least 1.
[[nodiscard]] VkExtent2D scaled_extent(VkExtent2D output, float scale);

} // namespace snell
