// Snell plugin toolkit: GGX prefiltering of a captured cube map for rough reflections (the
// split-sum approximation's radiance term, N = V = R: Karis 2013, Filament's IBL prefilter).
// A compute pass convolves a source cube (its level 0 and its box-filtered mip chain) with the
// GGX normal distribution into a destination cube: level k holds roughness
// k / (levels - 1), level 0 is an exact copy of the source's level 0 (a mirror). A surface reads
// it as `textureLod(cube, dir, roughness * (levels - 1))` (probe_lookup in
// shaders/snell/probe.glsl). The math, the sample counts and the cost: docs/runtime.md.
//
//   CubePrefilter prefilter = *CubePrefilter::create(ctx);                    // once
//   CubeTarget filtered = *CubeTarget::create(ctx, {.size = 256,
//       .color = ColorFormat::rgba16_float, .storage = true});               // once per size
//   CubePrefilterBinding job = *prefilter.bind(captured, filtered);          // once per pair
//   ...per frame, after record_cube_capture(cmd, scene, captured, ...):
//   prefilter.record(cmd, job, info.timer);
#pragma once

#include <snell/buffer.hpp>
#include <snell/images.hpp>
#include <snell/pipeline.hpp>
#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace snell {

class Context;
class GpuTimer;

/// The roughness that level `level` of a prefiltered cube of `levels` levels holds:
/// level / (levels - 1), in [0, 1] (perceptual roughness; the GGX alpha is its square). 0 for
/// `levels` <= 1 or level 0; 1 for level >= levels - 1. The inverse of the surface's lookup
/// `lod = roughness * (levels - 1)`.
[[nodiscard]] float cube_prefilter_roughness(std::uint32_t level, std::uint32_t levels);

/// Parameters of CubePrefilter::create.
struct CubePrefilterDesc {
  /// GPU timer scope of record() and the prefix of error messages. Required non-null. Default
  /// "cube_prefilter"; a plugin names its own ("dynamic_cubemap.prefilter").
  const char* name = "cube_prefilter";
  /// GGX samples per texel of the roughest levels (roughness >= 0.5); levels of roughness in
  /// [0.25, 0.5) take half as many and smoother levels a quarter, never fewer than 4 (see
  /// CubePrefilter::samples_at). Filtered importance sampling (each sample reads the source mip
  /// whose texels cover its share of the lobe) keeps a few dozen samples free of fireflies and
  /// aliasing. Range 4..256. Default 32 (32 / 16 / 8 per texel).
  std::uint32_t samples = 32;
};

/// What CubePrefilter::record reads and writes: one source cube and one destination cube, with
/// the destination's per-level storage views, descriptor sets and sample tables, all made once
/// by CubePrefilter::bind (RAII, move-only). It refers to the two cubes' images by handle, so
/// moving or swapping the CubeTarget objects does not invalidate it, but both cubes must outlive
/// it and it must outlive the command buffers that use it (retire it with DeferredRelease when
/// a cube is replaced). Nothing in it changes per frame.
class CubePrefilterBinding {
public:
  CubePrefilterBinding() = default;
  CubePrefilterBinding(CubePrefilterBinding&& other) noexcept;
  CubePrefilterBinding& operator=(CubePrefilterBinding&& other) noexcept;
  CubePrefilterBinding(const CubePrefilterBinding&) = delete;
  CubePrefilterBinding& operator=(const CubePrefilterBinding&) = delete;
  ~CubePrefilterBinding();

  /// Face size of both cubes in pixels (level 0).
  [[nodiscard]] std::uint32_t size() const { return size_; }
  /// Mip levels of both cubes (>= 2).
  [[nodiscard]] std::uint32_t levels() const { return levels_; }
  /// The source cube's colour image.
  [[nodiscard]] VkImage source() const { return source_; }
  /// The destination cube's colour image.
  [[nodiscard]] VkImage destination() const { return destination_; }
  [[nodiscard]] explicit operator bool() const { return pool_ != VK_NULL_HANDLE; }

private:
  friend class CubePrefilter;
  void reset();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage source_ = VK_NULL_HANDLE, destination_ = VK_NULL_HANDLE;
  std::uint32_t size_ = 0, levels_ = 0;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<VkImageView> level_views_{};     ///< Destination levels 1.. (2D array, 6 layers).
  std::vector<VkDescriptorSet> level_sets_{};  ///< Per destination level 1..levels-1.
  std::vector<std::uint32_t> level_samples_{}; ///< Samples per texel of levels 1..levels-1.
  Buffer table_{}; ///< The per-level sample tables (uniform, host-visible).
};

/// The GGX prefilter pass: a descriptor set layout and one compute pipeline per sample count
/// (the count is a specialization constant, so lavapipe compiles each loop once instead of
/// re-specialising per dispatch). Create it once per effect (RAII, move-only, must not outlive
/// its Context); bind() each source/destination pair once; record() per frame.
class CubePrefilter {
public:
  /// Builds the pipelines. Errors: invalid_argument (name null, samples outside 4..256),
  /// vulkan_error / out_of_memory naming `desc.name`.
  [[nodiscard]] static Result<CubePrefilter> create(const Context& ctx,
                                                    const CubePrefilterDesc& desc = {});

  CubePrefilter() = default;
  CubePrefilter(CubePrefilter&& other) noexcept;
  CubePrefilter& operator=(CubePrefilter&& other) noexcept;
  CubePrefilter(const CubePrefilter&) = delete;
  CubePrefilter& operator=(const CubePrefilter&) = delete;
  ~CubePrefilter();

  /// Prepares filtering `source` into `destination`: storage views of the destination's levels
  /// 1.., one descriptor set per level (the source's cube view with the context's linear_clamp
  /// sampler, the level's storage view, its sample table) and the sample tables (GGX directions,
  /// weights and source mip per sample, in a host-visible uniform buffer: no submission, so it
  /// may be called while a command buffer is being recorded). `source`: any colour format, a
  /// mip chain (CubeTargetDesc::mips) whose levels above 0 are the box-filtered chain
  /// (end_capture with mips, record_cube_capture). `destination`: the same size and number of
  /// levels, rgba16_float, CubeTargetDesc::storage, not the source itself. Errors:
  /// invalid_argument naming the cube and the mismatch (an empty cube, a different size or
  /// level count, fewer than 2 levels, no storage usage, the same cube twice), unsupported (a
  /// destination format other than rgba16_float), vulkan_error / out_of_memory.
  [[nodiscard]] Result<CubePrefilterBinding> bind(const CubeTarget& source,
                                                  const CubeTarget& destination) const;

  /// Records the pass, timed as CubePrefilterDesc::name when `timer` is given: the
  /// destination's level 0 becomes a copy of the source's level 0 (vkCmdCopyImage) and each
  /// level k >= 1 the GGX convolution of roughness cube_prefilter_roughness(k, levels) (one
  /// dispatch of 8 x 8 x 1 groups over its six faces). Expects both cubes as every capture
  /// leaves them (SHADER_READ_ONLY_OPTIMAL, writes visible to compute and transfer reads: after
  /// record_cube_capture / end_capture); leaves both there, the destination's writes visible to
  /// fragment, compute, vertex and transfer reads. Earlier reads of the destination (frames
  /// still sampling it) are ordered before its overwrite by the first barrier. The previous
  /// contents of the destination are discarded. Not recordable inside a rendering. Errors:
  /// invalid_argument for an empty prefilter or binding, or a binding of another prefilter's
  /// sample count.
  [[nodiscard]] Result<void> record(VkCommandBuffer cmd, const CubePrefilterBinding& binding,
                                    GpuTimer* timer = nullptr) const;

  /// Samples per texel for a level of roughness `roughness` (see CubePrefilterDesc::samples).
  [[nodiscard]] std::uint32_t samples_at(float roughness) const;
  /// The timer scope name (CubePrefilterDesc::name).
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] explicit operator bool() const { return set_layout_ != VK_NULL_HANDLE; }

private:
  void reset();
  /// The pipeline built for `count` samples per texel, or nullptr.
  [[nodiscard]] const Pipeline* pipeline_for(std::uint32_t count) const;
  const ContextState* ctx_ = nullptr;
  std::string name_{};
  std::uint32_t samples_ = 32;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  std::vector<std::uint32_t> counts_{}; ///< The sample counts of pipelines_, same order.
  std::vector<Pipeline> pipelines_{};
};

} // namespace snell
