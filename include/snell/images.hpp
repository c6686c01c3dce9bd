// Snell runtime: GPU images: sampled textures, render targets, cube targets, samplers.
// All are RAII and move-only, and must not outlive the Context they were created from.
#pragma once

#include <snell/context.hpp>
#include <snell/scene.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace snell {

/// Number of levels of a full mip chain for a `width` x `height` image: floor(log2(max)) + 1.
[[nodiscard]] std::uint32_t full_mip_count(std::uint32_t width, std::uint32_t height);

/// The largest width/height accepted for any image Snell creates (16384, the common
/// maxImageDimension2D of desktop GPUs; a device with a smaller limit reports its own).
inline constexpr std::uint32_t kMaxImageDimension = 16384;

/// Colour formats a render target can have.
enum class ColorFormat : std::uint8_t {
  rgba8_unorm, ///< 8-bit linear; what PNG readback writes verbatim.
  rgba8_srgb,  ///< 8-bit sRGB-encoded storage of linear shading results.
  rgba16_float ///< Half-float HDR; tone-mapped when written to PNG.
};

/// The VkFormat of a ColorFormat.
[[nodiscard]] VkFormat to_vk_format(ColorFormat format);

/// Parameters of RenderTarget::create.
struct RenderTargetDesc {
  std::uint32_t width = 0;  ///< Pixels, 1..kMaxImageDimension. No default: 0 is rejected.
  std::uint32_t height = 0; ///< Pixels, 1..kMaxImageDimension. No default: 0 is rejected.
  ColorFormat color = ColorFormat::rgba8_unorm; ///< Default rgba8_unorm.
  bool depth = true; ///< Also create a D32_SFLOAT depth image (sampleable). Default true.
  bool mips = false; ///< Full mip chain on the colour image (see generate_mips). Default false.
  const char* debug_name = "render target"; ///< Used in error messages.
};

/// Colour (+ optional depth) images to render into with dynamic rendering and then sample.
/// Samplable from creation on: colour is cleared to transparent black, depth to 1, both in
/// SHADER_READ_ONLY_OPTIMAL.
///
/// Layout protocol: `begin_rendering` transitions colour to COLOR_ATTACHMENT_OPTIMAL and depth
/// to DEPTH_ATTACHMENT_OPTIMAL; `end_rendering` (or `generate_mips`) leaves every level of colour,
/// and depth, in SHADER_READ_ONLY_OPTIMAL, synchronised for fragment and compute shader reads.
class RenderTarget {
public:
  /// Errors: invalid_argument naming the field (zero or oversize extent), out_of_memory.
  [[nodiscard]] static Result<RenderTarget> create(const Context& ctx,
                                                   const RenderTargetDesc& desc);

  RenderTarget() = default;
  RenderTarget(RenderTarget&&) noexcept;
  RenderTarget& operator=(RenderTarget&&) noexcept;
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;
  /// Exchanges the contents of two objects.
  void swap(RenderTarget& other) noexcept;
  ~RenderTarget();

  /// Barriers + vkCmdBeginRendering on level 0, clearing colour to `clear` (linear RGBA) and
  /// depth to `clear_depth` (default 1: far for depth [0,1]). `area` (pixels, clamped to the
  /// target) is the render area: only it is cleared, drawn and stored, and the rest of the
  /// target keeps its previous contents (the pass is cheaper by what it does not clear).
  /// Default {} (0 x 0): the whole target, previous contents discarded. Also sets a viewport
  /// over the whole target (standard, positive height) and the scissor to the area.
  void begin_rendering(VkCommandBuffer cmd, const float clear[4], float clear_depth = 1.0f,
                       VkRect2D area = {}) const;
  /// vkCmdEndRendering, then colour (all levels) and depth to SHADER_READ_ONLY_OPTIMAL; with
  /// mips, generates the chain first by linear blits.
  void end_rendering(VkCommandBuffer cmd) const;

  /// Renders on top of the finished colour and depth (both LOADed, after end_rendering), e.g.
  /// the surfaces phase after the scene snapshot. Pair with end_rendering.
  void continue_rendering(VkCommandBuffer cmd) const;

  /// Renders on top of the finished colour (level 0, no depth): LOAD instead of CLEAR, for
  /// overlays such as debug thumbnails. Pair with end_overlay.
  void begin_overlay(VkCommandBuffer cmd) const;
  /// Ends an overlay and returns colour to SHADER_READ_ONLY_OPTIMAL (regenerating mips).
  void end_overlay(VkCommandBuffer cmd) const;

  [[nodiscard]] std::uint32_t width() const { return width_; }
  [[nodiscard]] std::uint32_t height() const { return height_; }
  [[nodiscard]] std::uint32_t mip_levels() const { return mips_; }
  [[nodiscard]] ColorFormat color_format() const { return format_; }
  [[nodiscard]] VkFormat vk_color_format() const { return to_vk_format(format_); }
  [[nodiscard]] VkImage color_image() const { return color_; }
  [[nodiscard]] VkImageView color_view() const { return color_view_; } ///< All levels.
  [[nodiscard]] VkImage depth_image() const { return depth_; }
  [[nodiscard]] VkImageView depth_view() const { return depth_view_; }
  /// D32_SFLOAT with a depth image, UNDEFINED without.
  [[nodiscard]] VkFormat depth_format() const {
    return depth_ != VK_NULL_HANDLE ? VK_FORMAT_D32_SFLOAT : VK_FORMAT_UNDEFINED;
  }
  [[nodiscard]] explicit operator bool() const { return color_ != VK_NULL_HANDLE; }

private:
  friend Result<RenderTarget> create_render_target(const Context& ctx, const RenderTargetDesc& desc,
                                                   VkCommandBuffer clear_into);
  void reset();
  /// Ends the rendering and finishes colour (mips, SHADER_READ_ONLY_OPTIMAL).
  void finish_color(VkCommandBuffer cmd) const;
  const ContextState* ctx_ = nullptr;
  std::uint32_t width_ = 0, height_ = 0, mips_ = 1;
  ColorFormat format_ = ColorFormat::rgba8_unorm;
  VkImage color_ = VK_NULL_HANDLE, depth_ = VK_NULL_HANDLE;
  VkDeviceMemory color_memory_ = VK_NULL_HANDLE, depth_memory_ = VK_NULL_HANDLE;
  VkImageView color_view_ = VK_NULL_HANDLE, color_level0_view_ = VK_NULL_HANDLE,
              depth_view_ = VK_NULL_HANDLE;
};

/// Parameters of CubeTarget::create.
struct CubeTargetDesc {
  std::uint32_t size =
      256; ///< Face width = height in pixels, 1..kMaxImageDimension. Default 256 (seed 002).
  ColorFormat color = ColorFormat::rgba8_unorm; ///< Default rgba8_unorm.
  bool mips = true; ///< Full mip chain (for rough/blurred lookups). Default true.
  const char* debug_name = "cube target"; ///< Used in error messages.
  /// Also usable as a storage image (VK_IMAGE_USAGE_STORAGE_BIT): compute passes may write its
  /// levels, e.g. as the destination of a CubePrefilter (snell/toolkit/cube_prefilter.hpp).
  /// Needs a colour format with storage support (rgba8_unorm, rgba16_float; not rgba8_srgb:
  /// refused with `unsupported`). Default false: storage usage can make a driver choose a less
  /// efficient layout for sampling and attachments, so only cubes that need it ask for it.
  bool storage = false;
};

/// A six-layer cube colour image with a six-layer depth image, for environment capture.
/// Views: one per face (2D, level 0), a cube view (all levels, for sampling) and a 2D-array view
/// of level 0 (for multiview: one pass renders all six layers).
class CubeTarget {
public:
  [[nodiscard]] static Result<CubeTarget> create(const Context& ctx, const CubeTargetDesc& desc);

  CubeTarget() = default;
  CubeTarget(CubeTarget&&) noexcept;
  CubeTarget& operator=(CubeTarget&&) noexcept;
  CubeTarget(const CubeTarget&) = delete;
  CubeTarget& operator=(const CubeTarget&) = delete;
  /// Exchanges the contents of two objects.
  void swap(CubeTarget& other) noexcept;
  ~CubeTarget();

  /// Begins rendering into one face (layer `face`, level 0), clearing colour and depth, with a
  /// standard viewport. The first face begun after `end_capture` transitions the whole cube.
  void begin_face(VkCommandBuffer cmd, std::uint32_t face, const float clear[4]) const;
  void end_face(VkCommandBuffer cmd) const;
  /// Begins a multiview rendering of all six layers (viewMask 0b111111).
  void begin_multiview(VkCommandBuffer cmd, const float clear[4]) const;
  void end_multiview(VkCommandBuffer cmd) const;
  /// Transitions before any face is rendered this frame (all layers to attachment layouts).
  /// `keep_contents`: the faces not rendered this time keep their previous contents (a capture
  /// sliced over frames); otherwise everything is discarded (cheapest). Default false.
  void begin_capture(VkCommandBuffer cmd, bool keep_contents = false) const;
  /// After the faces: generates mips (when enabled) and leaves the cube SHADER_READ_ONLY.
  /// `mips`: rebuild the mip chain from level 0 (when the cube has one); false leaves the levels
  /// above 0 as they were (a slice whose cube is not complete yet). Default true.
  void end_capture(VkCommandBuffer cmd, bool mips = true) const;

  [[nodiscard]] std::uint32_t size() const { return size_; }
  [[nodiscard]] std::uint32_t mip_levels() const { return mips_; }
  [[nodiscard]] ColorFormat color_format() const { return format_; }
  /// Whether the colour image has storage usage (CubeTargetDesc::storage).
  [[nodiscard]] bool storage() const { return storage_; }
  [[nodiscard]] VkImage color_image() const { return color_; }
  [[nodiscard]] VkImageView cube_view() const { return cube_view_; }
  [[nodiscard]] VkImageView array_view() const { return array_view_; }
  [[nodiscard]] VkImageView face_view(std::uint32_t face) const { return face_views_[face % 6]; }
  [[nodiscard]] explicit operator bool() const { return color_ != VK_NULL_HANDLE; }

private:
  void reset();
  const ContextState* ctx_ = nullptr;
  std::uint32_t size_ = 0, mips_ = 1;
  ColorFormat format_ = ColorFormat::rgba8_unorm;
  bool storage_ = false;
  VkImage color_ = VK_NULL_HANDLE, depth_ = VK_NULL_HANDLE;
  VkDeviceMemory color_memory_ = VK_NULL_HANDLE, depth_memory_ = VK_NULL_HANDLE;
  VkImageView cube_view_ = VK_NULL_HANDLE, array_view_ = VK_NULL_HANDLE,
              depth_array_view_ = VK_NULL_HANDLE;
  VkImageView face_views_[6] = {}, depth_face_views_[6] = {};
};

/// A sampled 2D texture, uploaded once, with a full mip chain generated on the GPU.
class Texture2D {
public:
  /// Uploads an RGBA8 image (sRGB or linear per `image.srgb`). Errors name `image.name`.
  [[nodiscard]] static Result<Texture2D> create(const Context& ctx, const Image& image,
                                                bool mips = true);
  /// Loads PNG/JPEG/... with stb_image (errors name the file), then as above.
  [[nodiscard]] static Result<Texture2D> load(const Context& ctx, const std::filesystem::path& file,
                                              bool srgb = true, bool mips = true);

  Texture2D() = default;
  Texture2D(Texture2D&&) noexcept;
  Texture2D& operator=(Texture2D&&) noexcept;
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;
  /// Exchanges the contents of two objects.
  void swap(Texture2D& other) noexcept;
  ~Texture2D();

  [[nodiscard]] VkImage image() const { return image_; }
  [[nodiscard]] VkImageView view() const { return view_; }
  [[nodiscard]] std::uint32_t width() const { return width_; }
  [[nodiscard]] std::uint32_t height() const { return height_; }
  [[nodiscard]] std::uint32_t mip_levels() const { return mips_; }

private:
  void reset();
  const ContextState* ctx_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::uint32_t width_ = 0, height_ = 0, mips_ = 1;
};

/// Addressing of a sampler.
enum class AddressMode : std::uint8_t { repeat, mirrored_repeat, clamp_to_edge };

/// Parameters of Sampler::create.
struct SamplerDesc {
  bool linear = true;                        ///< Linear (else nearest) filtering. Default true.
  bool mipmaps = true;                       ///< Trilinear between levels. Default true.
  AddressMode address = AddressMode::repeat; ///< Default repeat.
  float max_anisotropy = 1.0f; ///< 1 = off; clamped to the device limit if anisotropy exists.
};

/// A VkSampler.
class Sampler {
public:
  [[nodiscard]] static Result<Sampler> create(const Context& ctx, const SamplerDesc& desc = {});
  Sampler() = default;
  Sampler(Sampler&&) noexcept;
  Sampler& operator=(Sampler&&) noexcept;
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;
  /// Exchanges the contents of two objects.
  void swap(Sampler& other) noexcept;
  ~Sampler();
  [[nodiscard]] VkSampler handle() const { return sampler_; }

private:
  const ContextState* ctx_ = nullptr;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

} // namespace snell
