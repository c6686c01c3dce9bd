// Snell: the scene snapshot. Between the opaque scene and the transmissive surfaces a frame
// copies the opaque colour (with a mip chain, for frosted lookups) and depth once into sampled
// images; every effect of the frame reads the same copy through FrameInfo::snapshot instead of
// rendering the scene again. A host records it with one call.
#pragma once

#include <snell/effect.hpp>
#include <snell/images.hpp>
#include <snell/toolkit/deferred_release.hpp>

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace snell {

/// The images a snapshot copies: the host's main colour and depth after its opaque phase
/// (its rendering ended). Both are returned to their layouts after the copy.
struct SnapshotSource {
  VkImage color = VK_NULL_HANDLE; ///< Required; created with TRANSFER_SRC usage.
  /// Its format: any format with BLIT_SRC support (converted to the snapshot's format).
  VkFormat color_format = VK_FORMAT_UNDEFINED;
  /// Its layout now and after the copy. Default COLOR_ATTACHMENT_OPTIMAL.
  VkImageLayout color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  /// Optional (VK_NULL_HANDLE: no depth copy); D32_SFLOAT with TRANSFER_SRC usage.
  VkImage depth = VK_NULL_HANDLE;
  /// Its layout now and after the copy. Default DEPTH_ATTACHMENT_OPTIMAL.
  VkImageLayout depth_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  VkExtent2D extent{0, 0};   ///< Size of both, pixels. Required.
  glm::mat4 view_proj{1.0f}; ///< The view-projection the images were rendered with.
  /// Build the colour copy's mip chain this frame (an effect samples blurred levels). Without
  /// it only level 0 (and depth) are this frame's. Default true.
  bool mips = true;
  /// The pixels to copy (clamped to `extent`): the union of what the effects sample
  /// (Effect::snapshot_region). Outside it the copy keeps older contents; mips are built from
  /// the whole of level 0. Extent 0 x 0: everything. Default {} (everything).
  VkRect2D region{};
};

/// The union of two pixel rectangles, where an extent of 0 x 0 means "everything" (so the union
/// with it is everything too).
[[nodiscard]] VkRect2D union_region(VkRect2D a, VkRect2D b);

/// Parameters of SceneSnapshot::create.
struct SnapshotDesc {
  /// Format of the colour copy when the source's format is none of ColorFormat's (then a blit
  /// converts). A source in rgba8_unorm, rgba8_srgb or rgba16_float is copied in its own format
  /// (a plain image copy: no conversion, half the bytes of a float copy for 8-bit sources).
  /// Default rgba16_float.
  ColorFormat color = ColorFormat::rgba16_float;
  bool mips = true;                   ///< A full mip chain on the colour copy. Default true.
  std::uint32_t frames_in_flight = 2; ///< Frames the host may have in flight, 1..16. Default 2.
};

/// The frame's copy of opaque colour and depth (RAII, move-only). Samplable from creation on
/// (cleared); after record(), colour (all levels) and depth are SHADER_READ_ONLY_OPTIMAL for
/// fragment and compute shaders.
class SceneSnapshot {
public:
  /// Errors: invalid_argument (frames_in_flight out of range).
  [[nodiscard]] static Result<SceneSnapshot> create(const Context& ctx,
                                                    const SnapshotDesc& desc = {});

  /// Records the copy of `source` (outside any rendering): resizes the images to the source
  /// (retiring the old ones past the frames in flight), blits colour level 0, builds the mips,
  /// copies depth, and returns the source images to their layouts. Errors: invalid_argument
  /// naming the field (no colour image, empty extent, depth not D32_SFLOAT), out_of_memory.
  [[nodiscard]] Result<void> record(VkCommandBuffer cmd, const SnapshotSource& source,
                                    std::uint64_t frame_index);

  [[nodiscard]] VkImageView color_view() const { return target_.color_view(); } ///< All levels.
  [[nodiscard]] VkImageView depth_view() const { return target_.depth_view(); }
  [[nodiscard]] VkImage color_image() const { return target_.color_image(); }
  [[nodiscard]] VkImage depth_image() const { return target_.depth_image(); }
  [[nodiscard]] VkFormat color_format() const { return target_.vk_color_format(); }
  [[nodiscard]] VkExtent2D extent() const { return {target_.width(), target_.height()}; }
  [[nodiscard]] std::uint32_t mip_levels() const { return target_.mip_levels(); }
  /// The view-projection of the copied images (SnapshotSource::view_proj), to reconstruct world
  /// positions from depth.
  [[nodiscard]] const glm::mat4& view_proj() const { return view_proj_; }
  /// How many copies record() has made since creation (one per frame: a test counts them).
  [[nodiscard]] std::uint64_t copies() const { return copies_; }
  /// The colour copy's levels 0 and 1 and its depth, for thumbnails.
  [[nodiscard]] std::vector<DebugTarget> debug_targets() const;

  SceneSnapshot() = default;
  SceneSnapshot(SceneSnapshot&&) noexcept = default;
  SceneSnapshot& operator=(SceneSnapshot&&) noexcept = default;
  SceneSnapshot(const SceneSnapshot&) = delete;
  SceneSnapshot& operator=(const SceneSnapshot&) = delete;
  ~SceneSnapshot() = default;

private:
  /// Returns the sources to their layouts and the copies to SHADER_READ_ONLY (mips if asked).
  void finish(VkCommandBuffer cmd, const SnapshotSource& src) const;
  const Context* ctx_ = nullptr;
  SnapshotDesc desc_;
  RenderTarget target_;
  DeferredRelease release_;
  glm::mat4 view_proj_{1.0f};
  std::uint64_t copies_ = 0;
};

} // namespace snell
