// Snell plugin toolkit: a descriptor-set builder with one set per frame in flight, so that an
// effect can point a binding at a new image (a resized target, a replaced texture) while earlier
// frames still execute with the old one: each frame's set is brought up to date only when that
// frame's slot comes round again, after the host has waited for its previous user.
#pragma once

#include <snell/result.hpp>
#include <snell/toolkit/uniform_ring.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace snell {

class Context;

/// One binding of the set.
struct DescriptorBinding {
  std::uint32_t binding = 0; ///< Binding number in the shader. Default 0.
  /// Descriptor type. Default COMBINED_IMAGE_SAMPLER.
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  /// Stages that read it. Default FRAGMENT.
  VkShaderStageFlags stages = VK_SHADER_STAGE_FRAGMENT_BIT;
  std::uint32_t count = 1; ///< Array size, >= 1. Default 1.
};

/// Parameters of DescriptorSets::create.
struct DescriptorSetDesc {
  std::vector<DescriptorBinding> bindings{}; ///< The layout. Required: at least one binding.
  /// Sets kept (one per frame in flight, EffectCreateInfo::frames_in_flight). 1..16. Default 2.
  std::uint32_t frames_in_flight = 2;
  const char* label = "descriptor set"; ///< Names the set in errors. Default "descriptor set".
};

/// A descriptor set layout and one set per frame in flight (RAII, move-only).
class DescriptorSets {
public:
  /// Errors: invalid_argument (no bindings, count 0, frames_in_flight out of range), vulkan_error.
  [[nodiscard]] static Result<DescriptorSets> create(const Context& ctx,
                                                     const DescriptorSetDesc& desc);

  DescriptorSets() = default;
  DescriptorSets(DescriptorSets&& other) noexcept;
  DescriptorSets& operator=(DescriptorSets&& other) noexcept;
  DescriptorSets(const DescriptorSets&) = delete;
  DescriptorSets& operator=(const DescriptorSets&) = delete;
  ~DescriptorSets();

  /// Points buffer binding `binding` (uniform / storage, dynamic or not) at `range` bytes of
  /// `buffer` from `offset`, from the next frame on.
  void set_buffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range,
                  std::uint32_t element = 0);
  /// Points image binding `binding` at `view` sampled with `sampler` in `layout` (default
  /// SHADER_READ_ONLY_OPTIMAL), from the next frame on.
  void set_image(std::uint32_t binding, VkImageView view, VkSampler sampler,
                 VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 std::uint32_t element = 0);

  /// The set of frame `frame_index` (slot frame_index % frames_in_flight), brought up to date
  /// with every set_* call so far. Valid while that frame records and executes.
  [[nodiscard]] VkDescriptorSet acquire(std::uint64_t frame_index);
  /// acquire() and vkCmdBindDescriptorSets at set number `set_index` of `layout`.
  void bind(VkCommandBuffer cmd, VkPipelineBindPoint bind_point, VkPipelineLayout layout,
            std::uint64_t frame_index, const std::uint32_t* dynamic_offsets = nullptr,
            std::uint32_t dynamic_offset_count = 0, std::uint32_t set_index = 0);

  [[nodiscard]] VkDescriptorSetLayout layout() const { return layout_; }
  [[nodiscard]] explicit operator bool() const { return layout_ != VK_NULL_HANDLE; }

private:
  struct Write {
    std::uint32_t binding = 0;
    std::uint32_t element = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    VkDescriptorBufferInfo buffer{};
    VkDescriptorImageInfo image{};
  };
  void reset();
  void store(const Write& write);
  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<DescriptorBinding> bindings_;
  std::vector<VkDescriptorSet> sets_;
  std::vector<std::uint64_t> applied_; ///< Per set: the version of writes_ it holds.
  std::vector<Write> writes_;
  std::uint64_t version_ = 1;
  std::string label_;
};

/// Parameters of create_surface_bindings.
struct SurfaceBindingsDesc {
  VkDeviceSize block_size = 0; ///< Bytes of the per-frame uniform block (std140). Required, > 0.
  /// Combined image samplers read by the fragment stage, at bindings 1..images. Default 0.
  std::uint32_t images = 0;
  /// More bindings after those (their binding numbers as given). Default none.
  std::vector<DescriptorBinding> extra{};
  /// EffectCreateInfo::frames_in_flight, 1..16. Default 2.
  std::uint32_t frames_in_flight = 2;
  const char* label = "surface bindings"; ///< Names the ring and the sets in errors.
};

/// The bindings most effect surfaces use, made together: a UniformRing of one block per frame
/// and the DescriptorSets whose binding 0 is that ring (a dynamic uniform buffer read by the
/// vertex and fragment stages, already pointed at the ring), bindings 1..images sampled images
/// (point them with set_image), then `extra`. Errors: those of UniformRing::create and
/// DescriptorSets::create; `ring` and `sets` are unchanged on error.
[[nodiscard]] Result<void> create_surface_bindings(const Context& ctx,
                                                   const SurfaceBindingsDesc& desc,
                                                   UniformRing& ring, DescriptorSets& sets);

} // namespace snell
